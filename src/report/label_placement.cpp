#include "report/label_placement.h"

#include <cmath>
#include <numbers>

namespace lt {

namespace {

bool inside(const Box& b, const Box& bounds) {
  return b.x >= bounds.x && b.y >= bounds.y && b.x + b.w <= bounds.x + bounds.w &&
         b.y + b.h <= bounds.y + bounds.h;
}

bool free_of(const Box& b, const std::vector<Box>& others) {
  for (const Box& o : others) {
    if (b.overlaps(o)) return false;
  }
  return true;
}

// Candidate spots around the anchor: the label's centre on rings 2 px apart, 24 angles each,
// right of the point first (where a reader looks for it).
template <class Accept>
bool search(const LabelRequest& r, const Box& bounds, Accept accept, Box& out) {
  const double reach = std::hypot(bounds.w, bounds.h);
  for (double radius = 0.5 * r.w + 5; radius <= reach; radius += 2) {
    for (int k = 0; k < 24; ++k) {
      const double a = 2 * std::numbers::pi * k / 24;
      const Box b{r.anchor_x + radius * std::cos(a) - 0.5 * r.w,
                  r.anchor_y - radius * std::sin(a) - 0.5 * r.h, r.w, r.h};
      if (accept(b)) {
        out = b;
        return true;
      }
    }
  }
  return false;
}

}  // namespace

std::vector<Box> place_labels(const std::vector<LabelRequest>& requests,
                              const std::vector<Box>& obstacles, const Box& bounds) {
  std::vector<Box> placed;
  for (const LabelRequest& r : requests) {
    Box b;
    const bool found = search(
        r, bounds,
        [&](const Box& c) {
          return inside(c, bounds) && free_of(c, placed) && free_of(c, obstacles);
        },
        b);
    if (!found) {
      // A plot too crowded for its markers: keep the labels apart at least, anywhere.
      Box unbounded = bounds;
      unbounded.x -= bounds.w, unbounded.y -= bounds.h, unbounded.w *= 3, unbounded.h *= 3;
      search(
          r, unbounded, [&](const Box& c) { return free_of(c, placed); }, b);
    }
    placed.push_back(b);
  }
  return placed;
}

}  // namespace lt
