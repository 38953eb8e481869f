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
    covered_ = gbuffer_.shade_covered(
        image_, s.background, [&](const PixelRun& run, ShadedRun& out, unsigned) {
          const Material& material = s.materials[run.material];
          for (size_t i = 0; i < run.count; ++i) {
            model::SurfacePoint sp;
            sp.P = glm::dvec3(run.position[0][i], run.position[1][i], run.position[2][i]);
            sp.N = glm::dvec3(run.normal[0][i], run.normal[1][i], run.normal[2][i]);
            sp.V = model::view_vector(s.camera, sp.P);
            sp.vertex_thickness =
                glm::dvec3(run.thickness[0][i], run.thickness[1][i], run.thickness[2][i]);
            sp.uv = glm::dvec2(run.uv[0][i], run.uv[1][i]);  // a map material's (u, v)
            const glm::dvec3 c = model::shade(s, material, sp);
            for (int ch = 0; ch < 3; ++ch) out.rgb[ch][i] = static_cast<float>(c[ch]);
          }
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
