// The contact sheet is for people: its labels are text drawn into the pixels, and they must be
// there (a sheet without them is the unlabelled grid issue 12 replaced).
#include "report/contact_sheet.h"

#include <gtest/gtest.h>

#include <array>
#include <utility>

#include "image/text.h"
#include "test_util.h"

namespace lt {
namespace {

size_t differing_pixels(const Image& a, const Image& b, int x0, int y0, int x1, int y1) {
  size_t n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const float* p = a.at(x, y);
      const float* q = b.at(x, y);
      n += p[0] != q[0] || p[1] != q[1] || p[2] != q[2];
    }
  }
  return n;
}

TEST(Text, DrawsALabelIntoThePixels) {
  ASSERT_FALSE(label_font().empty())
      << "no DejaVuSans.ttf: scripts/setup.sh installs fonts-dejavu-core";
  Image blank(200, 40), drawn(200, 40);
  const float ink[3] = {1, 1, 1};
  ASSERT_TRUE(draw_text(drawn, 4, 4, "backlit_sphere", 13, ink));
  // The ink lands where the text is, and only there.
  const int width = text_width("backlit_sphere", 13);
  EXPECT_GT(width, 60);
  EXPECT_LT(width, 140);
  EXPECT_GT(differing_pixels(blank, drawn, 4, 4, 4 + width, 4 + 16), 50u);
  EXPECT_EQ(differing_pixels(blank, drawn, 4 + width + 4, 0, 200, 40), 0u);
  // Another text is other pixels.
  Image other(200, 40);
  draw_text(other, 4, 4, "coloured_cubes", 13, ink);
  EXPECT_GT(differing_pixels(drawn, other, 0, 0, 200, 40), 20u);
}

TEST(ContactSheet, RowAndColumnLabelsAreInThePixels) {
  test::TempDir dir;
  Image grey(32, 24);
  for (float& v : grey.rgba) v = 0.5f;
  write_image(dir / "a.png", grey);
  ContactSheet labelled;
  labelled.row_labels = {"known_scene_label"};
  labelled.column_labels = {{"glsl", "pow=exact"}, {"gx", "t=vertex"}};
  labelled.cells = {{{dir / "a.png", dir / "a.png"}, {dir / "a.png", ""}}};
  ContactSheet unlabelled = labelled;
  unlabelled.row_labels = {""};
  unlabelled.column_labels = {{"", ""}, {"", ""}};
  const Image a = draw_contact_sheet(labelled), b = draw_contact_sheet(unlabelled);
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  // The row label sits left of the first thumbnail, the column labels above the thumbnails.
  const int label_column = text_width("known_scene_label", 13) + 8;
  EXPECT_GT(differing_pixels(a, b, 0, 0, label_column, a.height), 50u) << "row label";
  EXPECT_GT(differing_pixels(a, b, label_column, 0, a.width, 36), 50u) << "column labels";
  // The legend (the heatmap's ramp and its marks) is there in both, at the bottom.
  size_t coloured = 0;
  for (int x = 0; x < a.width; ++x) {
    for (int y = a.height - 48; y < a.height; ++y) {
      const float* p = a.at(x, y);
      coloured += p[0] != p[1] || p[1] != p[2];
    }
  }
  EXPECT_GT(coloured, 300u) << "no heatmap legend";
}

// The pixels of exactly this colour: their bounding box, x0 y0 x1 y1 (inclusive); x0 > x1 when
// there is none.
std::array<int, 4> box_of(const Image& img, const float rgb[3]) {
  std::array<int, 4> box = {img.width, img.height, -1, -1};
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      if (p[0] != rgb[0] || p[1] != rgb[1] || p[2] != rgb[2]) continue;
      box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x), std::max(box[3], y)};
    }
  }
  return box;
}

// A figure's pair (bench_contact_sheet.h): two renders in one row under their captions, and no
// heatmap legend on a sheet without heatmaps.
TEST(ContactSheet, APairSitsSideBySideUnderItsCaptions) {
  test::TempDir dir;
  const float red[3] = {1, 0, 0}, blue[3] = {0, 0, 1};
  for (const auto& [name, rgb] : {std::pair{"left.png", red}, std::pair{"right.png", blue}}) {
    Image img(64, 48);
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) img.at(x, y)[0] = rgb[0], img.at(x, y)[2] = rgb[2];
    for (int i = 0; i < img.width * img.height; ++i) img.rgba[4 * i + 3] = 1;
    write_image(dir / name, img);
  }
  ContactSheet pair;
  pair.row_labels = {"fig16 power"};
  pair.column_labels = {{"left", "reference"}, {"right", "reference"}};
  pair.cells = {{{dir / "left.png", "", "power 4"}, {dir / "right.png", "", "power 12"}}};
  pair.thumb_width = 64;
  pair.thumb_height = 48;
  ContactSheet uncaptioned = pair;
  for (ContactCell& c : uncaptioned.cells[0]) c.caption.clear();
  const Image a = draw_contact_sheet(pair), b = draw_contact_sheet(uncaptioned);
  const std::array<int, 4> left = box_of(a, red), right = box_of(a, blue);
  // Whole, at their size, in the same row, left before right.
  EXPECT_EQ(left[2] - left[0] + 1, 64);
  EXPECT_EQ(left[3] - left[1] + 1, 48);
  EXPECT_EQ(right[2] - right[0] + 1, 64);
  EXPECT_EQ(left[1], right[1]);
  EXPECT_EQ(left[3], right[3]);
  EXPECT_LT(left[2], right[0]);
  // The captions: ink above each render, where the uncaptioned sheet has none.
  const int caption_top = left[1] - 17;
  EXPECT_GT(differing_pixels(a, b, left[0], caption_top, left[2] + 1, left[1]), 20u);
  EXPECT_GT(differing_pixels(a, b, right[0], caption_top, right[2] + 1, right[1]), 20u);
  // No legend: nothing coloured but the two renders (text is grey).
  size_t coloured = 0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      const float* p = a.at(x, y);
      const bool grey = p[0] == p[1] && p[1] == p[2];
      const bool inside = (x >= left[0] && x <= left[2] && y >= left[1] && y <= left[3]) ||
                          (x >= right[0] && x <= right[2] && y >= right[1] && y <= right[3]);
      coloured += !grey && !inside;
    }
  }
  EXPECT_EQ(coloured, 0u);
  EXPECT_LT(a.height, left[3] + 20);  // the row is the sheet's last thing
}

}  // namespace
}  // namespace lt
