// A UV atlas of rectangular charts: where each chart of a multi-chart mesh (the teapot's
// patches) goes in [0, 1]^2, so that one texture holds them all without overlap.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace lt::meshgen {

// A chart's local (s, t) in [0, 1]^2 lands at offset + scale * (s, t).
struct ChartPlacement {
  glm::dvec2 offset{0.0};
  glm::dvec2 scale{1.0};
};

// Packs rectangles of the given sizes (any unit: only their ratios matter, so a texel covers
// the same surface on every chart when the sizes are the charts' surface lengths) into [0, 1]^2,
// as large as they fit, `gutter` apart (in atlas units; half of it at the atlas border) so that
// dilating one chart by less than gutter / 2 never reaches another. Shelf packing, tallest
// first; deterministic. Every size must be positive.
std::vector<ChartPlacement> pack_charts(const std::vector<glm::dvec2>& sizes, double gutter);

}  // namespace lt::meshgen
