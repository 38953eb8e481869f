#include "mesh/uv_atlas.h"

#include <algorithm>
#include <numeric>
#include <optional>

#include "core/error.h"

namespace lt::meshgen {

namespace {

// The shelf layout at `scale`, or nothing when it does not fit in the unit square.
std::optional<std::vector<ChartPlacement>> shelves(const std::vector<glm::dvec2>& sizes,
                                                   const std::vector<std::size_t>& order,
                                                   double scale, double gutter) {
  std::vector<ChartPlacement> out(sizes.size());
  const double border = gutter / 2;
  double x = border, y = border, shelf_height = 0.0;
  for (std::size_t k : order) {
    const glm::dvec2 size = scale * sizes[k];
    if (size.x + 2 * border > 1.0) return std::nullopt;
    if (x + size.x + border > 1.0) {
      // The next shelf starts a gutter above the tallest chart of this one.
      y += shelf_height + gutter;
      x = border;
      shelf_height = 0.0;
    }
    out[k] = {{x, y}, size};
    x += size.x + gutter;
    shelf_height = std::max(shelf_height, size.y);
  }
  if (y + shelf_height + border > 1.0) return std::nullopt;
  return out;
}

}  // namespace

std::vector<ChartPlacement> pack_charts(const std::vector<glm::dvec2>& sizes, double gutter) {
  LT_CHECK(!sizes.empty() && gutter >= 0.0 && gutter < 0.5, "charts to pack");
  double largest = 0.0;
  for (const auto& s : sizes) {
    LT_CHECK(s.x > 0.0 && s.y > 0.0, "chart sizes must be positive");
    largest = std::max({largest, s.x, s.y});
  }
  std::vector<std::size_t> order(sizes.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return sizes[a].y > sizes[b].y; });
  // Bisection on the scale: `low` always fits (a scale that makes every chart smaller than the
  // square divided among them does), `high` never does (the largest chart wider than the atlas).
  double low = 0.0, high = 1.0 / largest;
  auto best = shelves(sizes, order, low, gutter);
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    if (auto layout = shelves(sizes, order, mid, gutter)) {
      low = mid;
      best = std::move(layout);
    } else {
      high = mid;
    }
  }
  LT_CHECK(best && low > 0.0, "the charts fit in the atlas at some scale");
  return *best;
}

}  // namespace lt::meshgen
