// ltrender's own goldens, held by `ltrender regress` (one mechanism: what a studio runs on its
// scenes is what holds ours). Goldens are 8-bit PNGs at 320x240 of every demo scene
// (scenes/*.json) through the default variant of every path but flat, compared with the
// regress default tolerance (regress/regress_tolerance.h: 1 LSB on at most 0.5 % of the pixels,
// none over 3). The one deliberate way to change them is scripts/update_goldens.sh, which runs
// `ltrender regress scenes --goldens tests/goldens --width 320 --height 240 --update`.
//
// One test per case (piglit's rule: one process per GL test), each a regress run of that case.
#include <gtest/gtest.h>

#include "regress/regress.h"
#include "test_util.h"

namespace lt {
namespace {

// The size scripts/update_goldens.sh renders them at.
constexpr int kGoldenWidth = 320, kGoldenHeight = 240;

struct GoldenCase {
  fs::path scene;
  std::string path, variant;
};

void PrintTo(const GoldenCase& c, std::ostream* os) {
  *os << c.scene.stem().string() << " " << c.path << ":" << c.variant;
}

// The cases regress runs by default over scenes/, from the regress library's own lists.
std::vector<GoldenCase> golden_cases() {
  std::vector<GoldenCase> out;
  for (const fs::path& scene : collect_scene_files({test::source_dir() / "scenes"})) {
    for (const PathRequest& r : parse_path_list("")) {
      for (const std::string& v : r.variants) out.push_back({scene, r.path->name, v});
    }
  }
  return out;
}

class Golden : public ::testing::TestWithParam<GoldenCase> {};

TEST_P(Golden, MatchesWithinTolerance) {
  const GoldenCase& g = GetParam();
  RegressOptions o;
  o.inputs = {g.scene};
  o.goldens = test::source_dir() / "tests" / "goldens";
  o.paths = g.path + ":" + g.variant;
  o.width = kGoldenWidth;
  o.height = kGoldenHeight;
  o.quiet = true;
  const RegressRun run = run_regress(o);
  ASSERT_EQ(run.results.size(), 1u);
  const CaseResult& r = run.results.front();
  // Within the tolerance is a pass or, where the render differs from its golden at all (arbfp's
  // are 1 LSB off on a few pixels, as they were before the warn tier), regress's warn; else fail.
  EXPECT_TRUE(r.status == CaseStatus::kPass || r.status == CaseStatus::kWarn)
      << to_string(r.status) << ": " << r.message << "\n"
      << r.details << "(scripts/update_goldens.sh rewrites the goldens that fail)";
}

INSTANTIATE_TEST_SUITE_P(Renders, Golden, ::testing::ValuesIn(golden_cases()),
                         [](const auto& info) {
                           return info.param.scene.stem().string() + "__" + info.param.path;
                         });

}  // namespace
}  // namespace lt
