#include "metrics/heatmap.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/error.h"

namespace lt {

namespace {

// Equally spaced stops. Brightness rises along the ramp (blue is darker than green, yellow
// brighter than red, white brightest) except red after yellow, where the hue change is loud
// enough to read as "worse".
constexpr float kRamp[][3] = {
    {0.0f, 0.0f, 0.0f},  // black: no error
    {0.0f, 0.0f, 1.0f},  // blue
    {0.0f, 1.0f, 0.0f},  // green
    {1.0f, 1.0f, 0.0f},  // yellow
    {1.0f, 0.0f, 0.0f},  // red
    {1.0f, 1.0f, 1.0f},  // white: max_lsb and beyond
};
constexpr int kSegments = static_cast<int>(std::size(kRamp)) - 1;

// Errors at or under this are what rounding to 8 bits alone gives (metrics.md's floor).
constexpr double kEightBitFloorLsb = 0.5;

}  // namespace

void heatmap_colour(double error_lsb, double max_lsb, float rgb[3]) {
  const double t = std::clamp(error_lsb / max_lsb, 0.0, 1.0) * kSegments;
  const int i = std::min(static_cast<int>(t), kSegments - 1);
  const float f = static_cast<float>(t - i);
  for (int c = 0; c < 3; ++c) rgb[c] = kRamp[i][c] + (kRamp[i + 1][c] - kRamp[i][c]) * f;
}

Image error_heatmap(const Comparison& comparison, double max_lsb) {
  LT_CHECK(max_lsb > 0.0 && std::isfinite(max_lsb), "heatmap scale must be finite and > 0");
  LT_CHECK(comparison.pixel_error_lsb.size() ==
               static_cast<size_t>(comparison.width) * comparison.height,
           "comparison has no per-pixel errors");
  Image heat(comparison.width, comparison.height);
  for (size_t i = 0; i < heat.pixel_count(); ++i) {
    const double e = comparison.pixel_error_lsb[i];
    float* d = &heat.rgba[i * 4];
    if (!std::isfinite(e)) {
      std::copy_n(kHeatmapNonFinite, 3, d);
    } else if (!comparison.covered_mask[i] && e <= kEightBitFloorLsb) {
      std::copy_n(kHeatmapUncovered, 3, d);
    } else {
      heatmap_colour(e, max_lsb, d);
    }
    d[3] = 1.0f;
  }
  return heat;
}

}  // namespace lt
