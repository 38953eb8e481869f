// Offscreen regression renders against goldens (Filament's rule: compared by default, updated
// only by one deliberate command: scripts/update_goldens.sh, which runs these tests with
// LT_UPDATE_GOLDENS=1). Goldens are 8-bit PNGs at 320x240 of every demo scene through the
// default variant of every path but flat: a change to any path's output shows up here.
//
// Tolerance (piglit's rule: it follows from the framebuffer's bits): a pixel may differ by 1 LSB
// (rounding of a value that sits on a half-LSB boundary after a Mesa or compiler change) on at
// most 0.5 % of the covered pixels, and no pixel by more than 3 LSB.
#include <gtest/gtest.h>

#include <cstdlib>

#include "metrics/compare.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

constexpr int kGoldenWidth = 320, kGoldenHeight = 240;

struct GoldenCase {
  std::string scene, path;
};

void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.scene << " " << c.path;
}

std::vector<GoldenCase> golden_cases() {
  std::vector<GoldenCase> out;
  std::vector<fs::path> scenes;
  for (const auto& e : fs::directory_iterator(test::source_dir() / "scenes")) {
    if (e.path().extension() == ".json") scenes.push_back(e.path());
  }
  std::sort(scenes.begin(), scenes.end());
  for (const auto& s : scenes) {
    for (const PathInfo& p : all_paths()) {
      if (p.role == PathRole::Baseline) continue;  // a timing baseline, not a rendering to keep
      out.push_back({s.stem().string(), p.name});
    }
  }
  return out;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesWithinThreeLsb) {
  const GoldenCase& g = GetParam();
  const Scene scene = load_scene(test::source_dir() / "scenes" / (g.scene + ".json"));
  const Image img = render_scene(scene, g.path, "", kGoldenWidth, kGoldenHeight);
  const fs::path golden =
      test::source_dir() / "tests" / "goldens" / (g.scene + "__" + g.path + ".png");
  if (std::getenv("LT_UPDATE_GOLDENS")) {
    write_image(golden, img);
    GTEST_SKIP() << "updated " << golden;
  }
  ASSERT_TRUE(fs::exists(golden)) << golden << " is missing: run scripts/update_goldens.sh";
  Image expected = read_image(golden);
  // The golden PNG carries no coverage; take it from the render so background counts too.
  Tolerance tol;
  tol.fail_lsb = 1.0;
  tol.fail_percent = 0.5;
  tol.hard_fail_lsb = 3.0;
  tol.region = Region::kImage;
  const Comparison c = compare_images(img, expected, TestEncoding::kUnorm8);
  const Verdict v = judge(c, tol);
  EXPECT_TRUE(v.pass) << to_table(c, tol, v);
}

INSTANTIATE_TEST_SUITE_P(Renders, Golden, ::testing::ValuesIn(golden_cases()),
                         [](const auto& info) {
                           return info.param.scene + "__" + info.param.path;
                         });

}  // namespace
}  // namespace lt
