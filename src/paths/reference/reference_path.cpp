#include "paths/reference/reference_path.h"

#include "core/simd_target.h"
#include "paths/common/cpu_shaded_path.h"
#include "paths/reference/reference_shading_lanes.h"

namespace lt {

namespace {

class ReferencePath final : public CpuShadedPath {
 public:
  explicit ReferencePath(const PathContext& ctx)
      : CpuShadedPath(ctx, "the reference G-buffer",
                      "model::shade in double " + simd_target() + " vector lanes"),
        relative_scene_(camera_relative_lights(ctx)) {}

 private:
  void shade() override {
    const Scene& s = relative_scene_;
    covered_ = gbuffer_.shade_covered(
        image_, s.background, [&](const PixelRun& run, ShadedRun& out, unsigned) {
          reference::shade_run(s, s.materials[run.material], run, out);
        });
  }

  Scene relative_scene_;
};

}  // namespace

const PathInfo& reference_path_info() {
  static const SingleVariantInfo<ReferencePath> info(
      "reference", "double precision on the CPU over a float G-buffer: the ground truth",
      {"exact", "double precision, a whole power of t correctly rounded; the only variant"},
      PathRole::GroundTruth);
  return info;
}

}  // namespace lt
