// False-colour picture of where a Comparison's error is, for a person to look at (`ltrender
// compare --heatmap`, the bench report). The scale is fixed, not normalised to the image's own
// max, so two heatmaps on the same scale can be compared by eye.
#pragma once

#include "image/image.h"
#include "metrics/compare.h"

namespace lt {

// Default top of the scale: 8 LSB, so the 0.5 LSB floor of 8-bit output is near black and the
// 1 and 4 LSB marks of the report fall on the ramp's first and third colours.
inline constexpr double kHeatmapMaxLsb = 8.0;

// Covered pixels go through black -> blue -> green -> yellow -> red -> white on [0, max_lsb]
// (white beyond). Uncovered pixels are dark grey unless their error is over the 8-bit floor
// (0.5 LSB): the grey shows the coverage, and geometry drawn where the reference has none still
// shows in colour. Pixels with a non-finite TEST value are magenta, a colour the ramp never
// takes. Alpha is 1. max_lsb must be > 0 (LT_CHECK).
Image error_heatmap(const Comparison& comparison, double max_lsb = kHeatmapMaxLsb);

// The ramp: colour (linear RGB in [0, 1]) of an error of `error_lsb` on a scale [0, max_lsb].
void heatmap_colour(double error_lsb, double max_lsb, float rgb[3]);

inline constexpr float kHeatmapUncovered[3] = {0.2f, 0.2f, 0.2f};
inline constexpr float kHeatmapNonFinite[3] = {1.0f, 0.0f, 1.0f};

}  // namespace lt
