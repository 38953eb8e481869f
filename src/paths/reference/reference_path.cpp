#include "paths/reference/reference_path.h"

#include <chrono>
#include <thread>

#include "model/translucency.h"
#include "paths/common/gbuffer.h"

namespace lt {

namespace {

class ReferencePath final : public Path {
 public:
  explicit ReferencePath(const PathContext& ctx)
      : ctx_(ctx),
        gbuffer_(ctx, "the reference G-buffer"),
        relative_scene_(camera_relative_lights(ctx)) {}

  void frame() override {
    gbuffer_.rasterise();
    const auto t0 = std::chrono::steady_clock::now();
    shade();
    shading_seconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  Image result() override { return image_; }
  bool float_output() const override { return true; }

  std::vector<BuiltStage> stages() const override {
    std::vector<BuiltStage> out = gbuffer_.stages();
    out.push_back({"shading: model::shade in double on " + std::to_string(threads()) + " threads",
                   "cpu", ""});
    return out;
  }

  FrameStats frame_stats() const override {
    FrameStats s;
    s.shading_seconds = shading_seconds_;
    s.covered_pixels = static_cast<double>(covered_);
    s.threads = threads();
    return s;
  }

 private:
  static unsigned threads() { return GBuffer::threads(); }

  void shade() {
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
      const glm::dvec3 c = model::shade(s, s.materials[gbuffer_.material(g)], sp);
      for (int ch = 0; ch < 3; ++ch) out[ch] = static_cast<float>(c[ch]);
    });
  }

  PathContext ctx_;
  GBuffer gbuffer_;
  Scene relative_scene_;
  Image image_;
  double shading_seconds_ = 0;
  size_t covered_ = 0;
};

}  // namespace

PathInfo reference_path_info() {
  PathInfo info{"reference",
                "double precision on the CPU over a float G-buffer: the ground truth",
                {{"exact", "std::pow in double; the only variant"}},
                [](const PathContext& ctx, const std::string&) -> std::unique_ptr<Path> {
                  return std::make_unique<ReferencePath>(ctx);
                }};
  info.role = PathRole::GroundTruth;
  return info;
}

}  // namespace lt
