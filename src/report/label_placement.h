// Labels that never overlap (the chart's point numbers): each label goes to the first free spot
// around its point, searched in rings of growing distance, so close points push their labels
// apart instead of printing them over each other.
#pragma once

#include <vector>

namespace lt {

struct Box {
  double x = 0, y = 0, w = 0, h = 0;  // top-left corner and size
  bool overlaps(const Box& o) const {
    return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
};

struct LabelRequest {
  double anchor_x = 0, anchor_y = 0;  // the point the label names
  double w = 0, h = 0;                // the label's size
};

// One box per request, in order: inside `bounds`, overlapping no other box and no obstacle (the
// chart's markers). A request for which no free spot exists within the bounds is given the
// spot nearest its point that overlaps no other label (obstacles aside): labels never overlap
// each other.
std::vector<Box> place_labels(const std::vector<LabelRequest>& requests,
                              const std::vector<Box>& obstacles, const Box& bounds);

}  // namespace lt
