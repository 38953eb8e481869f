// The talk's figures as pairs: two scenes of one parameter, left and right, are one row of the
// contact sheet (report/figure_pairs.h, report/bench_contact_sheet.h).
#include "report/figure_pairs.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "report/bench_contact_sheet.h"
#include "test_util.h"

namespace lt {
namespace {

TEST(FigurePairs, TheFiguresScenesPairAsTheTalkShowsThem) {
  // The scenes of scenes/figures/, in the order bench gets them from the shell's glob.
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(test::source_dir() / "scenes" / "figures"))
    if (e.path().extension() == ".json") names.push_back(e.path().stem().string());
  std::sort(names.begin(), names.end());
  ASSERT_EQ(names.size(), 13u);
  const std::vector<FigureRow> rows = figure_rows(names);
  std::vector<std::string> labels, captions;
  for (const FigureRow& r : rows) {
    labels.push_back(r.label);
    ASSERT_EQ(r.scenes.size(), r.captions.size());
    for (const std::string& c : r.captions) captions.push_back(c);
  }
  // Fig. 14-17 one parameter each, Fig. 20/21 grey against red on the per-vertex bake, their
  // map twins, and Fig. 22 alone.
  EXPECT_EQ(labels, (std::vector<std::string>{"fig14 ambient", "fig15 scale", "fig16 power",
                                              "fig17 distortion", "fig20/fig21 thickness",
                                              "fig21m thickness", "fig22_coloured_cubes"}));
  EXPECT_EQ(captions, (std::vector<std::string>{"ambient 0", "ambient 0.2", "scale 1", "scale 5",
                                                "power 4", "power 12", "distortion 0",
                                                "distortion 0.2", "thickness grey", "thickness red",
                                                "thickness grey map", "thickness red map", ""}));
  // Each pair is two neighbours, left (a) first.
  for (const FigureRow& r : rows) {
    if (r.scenes.size() != 2) continue;
    EXPECT_EQ(r.scenes[1], r.scenes[0] + 1);
    EXPECT_NE(names[r.scenes[0]].find("_a_"), std::string::npos) << r.label;
    EXPECT_NE(names[r.scenes[1]].find("_b_"), std::string::npos) << r.label;
  }
}

TEST(FigurePairs, OnlyALeftFollowedByARightOfTheSameParameterPairs) {
  // b before a, two parameters, an a with nothing after it: no pair, so no figure sheet.
  EXPECT_TRUE(figure_rows({"f1_power_b_4", "f1_power_a_12"}).empty());
  EXPECT_TRUE(figure_rows({"f1_power_a_4", "f1_scale_b_2"}).empty());
  EXPECT_TRUE(figure_rows({"f1_power_a_4"}).empty());
  // The demo scenes have no figure in their names.
  EXPECT_TRUE(figure_rows({"backlit_sphere", "baked_blob", "coloured_cubes", "thin_vs_thick",
                           "three_point_blob", "backlit_sphere_ortho"})
                  .empty());
  // A value needs a token after the side, a parameter one before it.
  EXPECT_TRUE(figure_rows({"f1_a_4", "f1_b_12"}).empty());
  EXPECT_TRUE(figure_rows({"f1_power_a", "f1_power_b"}).empty());
  const std::vector<FigureRow> one = figure_rows({"x", "f1_power_a_4", "f1_power_b_12", "y"});
  ASSERT_EQ(one.size(), 3u);
  EXPECT_EQ(one[0].label, "x");
  EXPECT_EQ(one[1].scenes, (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(one[2].label, "y");
}

BenchRow figure_row(const std::string& scene, const std::string& path, const std::string& variant) {
  BenchRow r;
  r.scene = scene;
  r.path = path;
  r.variant = variant;
  r.image = "images/" + scene + "__" + path + ".png";
  if (path != "flat" && path != "reference") r.heatmap = "images/" + scene + "__heatmap.png";
  r.width = 320;
  r.height = 240;
  return r;
}

TEST(BenchContactSheet, TwoScenesOfOneFigureLandInOneRow) {
  // demo.sh's figures bench: --paths reference, and flat, which always runs.
  const std::vector<BenchRow> rows = {figure_row("fig15_scale_a_1", "reference", "exact"),
                                      figure_row("fig15_scale_a_1", "flat", "constant"),
                                      figure_row("fig15_scale_b_5", "reference", "exact"),
                                      figure_row("fig15_scale_b_5", "flat", "constant")};
  const ContactSheet sheet = bench_contact_sheet("out", rows);
  ASSERT_EQ(sheet.row_labels, (std::vector<std::string>{"fig15 scale"}));
  // Left and right, the reference each (flat's constant colour tells nothing of a parameter).
  ASSERT_EQ(sheet.column_labels, (std::vector<std::pair<std::string, std::string>>{
                                     {"left", "reference"}, {"right", "reference"}}));
  ASSERT_EQ(sheet.cells.size(), 1u);
  ASSERT_EQ(sheet.cells[0].size(), 2u);
  EXPECT_EQ(sheet.cells[0][0].image, fs::path("out/images/fig15_scale_a_1__reference.exr"));
  EXPECT_EQ(sheet.cells[0][1].image, fs::path("out/images/fig15_scale_b_5__reference.exr"));
  EXPECT_EQ(sheet.cells[0][0].caption, "scale 1");
  EXPECT_EQ(sheet.cells[0][1].caption, "scale 5");
  // At the scenes' own size: a pair is compared in its detail.
  EXPECT_EQ(sheet.thumb_width, 320);
  EXPECT_EQ(sheet.thumb_height, 240);
}

TEST(BenchContactSheet, APortsRenderSitsBesideTheReferenceOnEachSide) {
  const std::vector<BenchRow> rows = {figure_row("fig16_power_a_4", "reference", "exact"),
                                      figure_row("fig16_power_a_4", "gx", "t=vertex"),
                                      figure_row("fig16_power_a_4", "gx", "t=vertex:lut=16"),
                                      figure_row("fig16_power_b_12", "reference", "exact"),
                                      figure_row("fig16_power_b_12", "gx", "t=vertex")};
  const ContactSheet sheet = bench_contact_sheet("out", rows);
  ASSERT_EQ(sheet.column_labels,
            (std::vector<std::pair<std::string, std::string>>{{"left", "reference"},
                                                              {"left", "gx t=vertex"},
                                                              {"right", "reference"},
                                                              {"right", "gx t=vertex"}}));
  ASSERT_EQ(sheet.cells.size(), 1u);
  EXPECT_EQ(sheet.cells[0][1].image, fs::path("out/images/fig16_power_a_4__gx.png"));
  EXPECT_EQ(sheet.cells[0][1].heatmap, fs::path("out/images/fig16_power_a_4__heatmap.png"));
  EXPECT_EQ(sheet.cells[0][3].image, fs::path("out/images/fig16_power_b_12__gx.png"));
  EXPECT_EQ(sheet.cells[0][3].caption, "power 12");
}

TEST(BenchContactSheet, OtherScenesKeepARowEach) {
  const std::vector<BenchRow> rows = {figure_row("backlit_sphere", "glsl", "pow=exact"),
                                      figure_row("backlit_sphere", "glsl", "pow=exact:f32"),
                                      figure_row("backlit_sphere", "flat", "constant"),
                                      figure_row("baked_blob", "glsl", "pow=exact"),
                                      figure_row("baked_blob", "flat", "constant")};
  const ContactSheet sheet = bench_contact_sheet("out", rows);
  EXPECT_EQ(sheet.row_labels, (std::vector<std::string>{"backlit_sphere", "baked_blob"}));
  // The reference, then each path's default variant (flat included), no captions.
  EXPECT_EQ(sheet.column_labels,
            (std::vector<std::pair<std::string, std::string>>{
                {"reference", "(float, clamped)"}, {"glsl", "pow=exact"}, {"flat", "constant"}}));
  EXPECT_EQ(sheet.cells[1][1].image, fs::path("out/images/baked_blob__glsl.png"));
  EXPECT_EQ(sheet.cells[1][1].caption, "");
  EXPECT_EQ(sheet.thumb_width, ContactSheet{}.thumb_width);
}

}  // namespace
}  // namespace lt
