// The contact sheet is for people: its labels are text drawn into the pixels, and they must be
// there (a sheet without them is the unlabelled grid issue 12 replaced).
#include "report/contact_sheet.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lt
