#include "paths/reference/reference_path.h"

#include "model/translucency.h"
#include "paths/common/cpu_shaded_path.h"

namespace lt {

namespace {

class ReferencePath final : public CpuShadedPath {
 public:
  explicit ReferencePath(const PathContext& ctx)
      : CpuShadedPath(ctx, "the reference G-buffer", "model::shade in double"),
        relative_scene_(camera_relative_lights(ctx)) {}

 private:
  void shade() override {
    const Scene& s = relative_scene_;
    covered_ = gbuffer_.shade_covered(image_, s.background, [&](size_t g, float* out, unsigned) {
      const float* pos = gbuffer_.position(g);
      const float* nrm = gbuffer_.normal(g);
      const float* thk = gbuffer_.thickness(g);
      model::SurfacePoint sp;
      sp.P = glm::dvec3(pos[0], pos[1], pos[2]);
      sp.N = glm::dvec3(nrm[0], nrm[1], nrm[2]);
      sp.V = model::view_vector(s.camera, sp.P);
      sp.vertex_thickness = glm::dvec3(thk[0], thk[1], thk[2]);
      sp.uv = gbuffer_.uv(g);  // a map material's (u, v)
      const glm::dvec3 c = model::shade(s, s.materials[gbuffer_.material(g)], sp);
      for (int ch = 0; ch < 3; ++ch) out[ch] = static_cast<float>(c[ch]);
    });
  }

  Scene relative_scene_;
};

}  // namespace

const PathInfo& reference_path_info() {
  static const SingleVariantInfo<ReferencePath> info(
      "reference", "double precision on the CPU over a float G-buffer: the ground truth",
      {"exact", "std::pow in double; the only variant"}, PathRole::GroundTruth);
  return info;
}

}  // namespace lt
