// Where bench and advise class a port's error against the float reference into edge shifts and
// shading (split_edge_shifts): at 1 LSB, the figure `% > 1 LSB` counts over, so the two counts
// split exactly those pixels. A port's own rounding to 8 bits stays at or under 0.5 LSB, so what
// is classed is the port's real error; regress classes at its tolerance's fail_lsb instead.
#pragma once

#include "metrics/compare.h"

namespace lt {

inline constexpr double kReferenceEdgeSplitLsb = 1.0;

// The covered pixels of `comparison` (a port against the reference) classed at that threshold.
inline EdgeShiftSplit reference_edge_split(const Comparison& comparison) {
  return split_edge_shifts(comparison, kReferenceEdgeSplitLsb, Region::kCovered);
}

}  // namespace lt
