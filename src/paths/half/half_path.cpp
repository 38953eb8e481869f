#include "paths/half/half_path.h"

#include <cmath>

#include "core/simd_target.h"
#include "paths/common/cpu_shaded_path.h"
#include "paths/half/half_shading.h"
#include "paths/half/half_shading_lanes.h"

namespace lt {

namespace {

// What a pixel the unguarded mode made NaN or Inf is written as: magenta, covered. "No NaN or
// Inf ever reaches an image" (model.md), yet the failure must stay visible, not blend in: no
// lit translucent surface is pure (1, 0, 1). The pixels are also counted in frame_stats.
constexpr float kNonFiniteMarker[3] = {1, 0, 1};

class HalfPath final : public CpuShadedPath {
 public:
  HalfPath(const PathContext& ctx, fp16::PowMode mode)
      : CpuShadedPath(ctx, "the half path's G-buffer",
                      "fp16 emulation in " + simd_target() + " vector lanes"),
        mode_(mode) {
    // The shader sees the G-buffer's camera-relative space, so its light positions are too.
    const Scene relative = camera_relative_lights(ctx);
    scene_ = fp16::prepare_scene(relative, mode_);
    background_ = relative.background;
  }

  FrameStats frame_stats() const override {
    FrameStats s = CpuShadedPath::frame_stats();
    s.nonfinite_pixels = static_cast<double>(nonfinite_);
    return s;
  }

 private:
  void shade() override {
    std::vector<size_t> nonfinite(threads(), 0);
    covered_ = gbuffer_.shade_covered(
        image_, background_, [&](const PixelRun& run, ShadedRun& out, unsigned w) {
          fp16::shade_run(scene_, scene_.materials[run.material], mode_, run, out);
          for (size_t i = 0; i < run.count; ++i) {
            const bool finite = std::isfinite(out.rgb[0][i]) && std::isfinite(out.rgb[1][i]) &&
                                std::isfinite(out.rgb[2][i]);
            nonfinite[w] += !finite;
            if (!finite) {
              for (int ch = 0; ch < 3; ++ch) out.rgb[ch][i] = kNonFiniteMarker[ch];
            }
          }
        });
    nonfinite_ = 0;
    for (size_t n : nonfinite) nonfinite_ += n;
  }

  fp16::PowMode mode_;
  fp16::SceneH scene_;
  glm::dvec3 background_{0};
  size_t nonfinite_ = 0;
};

// The variants are the pow modes of half_shading.h, one name each.
class HalfInfo final : public ListedPathInfo<fp16::PowMode> {
 public:
  HalfInfo()
      : ListedPathInfo(
            "half",
            "the seed's half3 arithmetic emulated on the CPU (IEEE binary16 after every "
            "operation)",
            {{{"pow=exact",
               "exp2(p * log2(t)) in half, the way fp16 POW does it, hard cases guarded"},
              fp16::PowMode::Exact},
             {{"pow=sg", "spherical-Gaussian exp2(t * n' - n') in half, hard cases guarded"},
              fp16::PowMode::Sg},
             {{"pow=unguarded",
               "exp2(p * log2(t)) with no guards: NaN/Inf pixels counted (nonfinite_pixels) and "
               "drawn magenta"},
              fp16::PowMode::Unguarded}}) {}
  std::unique_ptr<Path> build(const PathContext& ctx, const fp16::PowMode& mode) const override {
    return std::make_unique<HalfPath>(ctx, mode);
  }
};

}  // namespace

const PathInfo& half_path_info() {
  static const HalfInfo info;
  return info;
}

}  // namespace lt
