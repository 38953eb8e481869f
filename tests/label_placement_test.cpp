// The chart's labels never overlap, however close the points are.
#include "report/label_placement.h"

#include <gtest/gtest.h>

namespace lt {
namespace {

void expect_apart(const std::vector<Box>& boxes, const std::vector<Box>& obstacles,
                  const Box& bounds) {
  for (size_t i = 0; i < boxes.size(); ++i) {
    for (size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << i << " and " << j;
    for (const Box& o : obstacles) EXPECT_FALSE(boxes[i].overlaps(o)) << i << " on a marker";
    EXPECT_GE(boxes[i].x, bounds.x);
    EXPECT_LE(boxes[i].x + boxes[i].w, bounds.x + bounds.w);
  }
}

TEST(LabelPlacement, PointsOnOneSpotGetLabelsApartAndOffTheMarkers) {
  const Box bounds{0, 0, 600, 400};
  std::vector<LabelRequest> requests;
  std::vector<Box> markers;
  for (int i = 0; i < 30; ++i) {
    requests.push_back({300, 200, 16, 12});
    markers.push_back({294, 194, 12, 12});
  }
  expect_apart(place_labels(requests, markers, bounds), markers, bounds);
}

TEST(LabelPlacement, CloseRowOfPointsAndTheNearestSpotFirst) {
  const Box bounds{0, 0, 600, 400};
  std::vector<LabelRequest> requests;
  std::vector<Box> markers;
  for (int i = 0; i < 22; ++i) {
    requests.push_back({100.0 + 3 * i, 50, 16, 12});
    markers.push_back({94.0 + 3 * i, 44, 12, 12});
  }
  const auto boxes = place_labels(requests, markers, bounds);
  expect_apart(boxes, markers, bounds);
  // A lone point's label goes right beside it.
  const auto lone = place_labels({{300, 200, 16, 12}}, {{294, 194, 12, 12}}, bounds);
  EXPECT_LT(std::abs(lone[0].x + 8 - 300) + std::abs(lone[0].y + 6 - 200), 30);
}

TEST(LabelPlacement, ACrowdedPlotStillKeepsLabelsApart) {
  const Box bounds{0, 0, 60, 40};  // room for far fewer labels than asked
  std::vector<LabelRequest> requests(40, LabelRequest{30, 20, 16, 12});
  const auto boxes = place_labels(requests, {}, bounds);
  for (size_t i = 0; i < boxes.size(); ++i) {
    for (size_t j = i + 1; j < boxes.size(); ++j)
      EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << i << " and " << j;
  }
}

}  // namespace
}  // namespace lt
