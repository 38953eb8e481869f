// The pass planner finds the fewest passes (arb_pass_search.h): against every partition of the
// lights of a scene whose consecutive runs need more passes than the optimum, and against the
// capacity bound on the over-budget scenes.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "arb_pass_util.h"
#include "arb_test_util.h"
#include "budget_test_util.h"
#include "paths/arbfp/arb_passes.h"

namespace lt {
namespace {

// Two directional lights, four point lights, two directional lights (twelve_mixed's and
// eight_directional's): consecutive runs under arbfp1-min (48 ALU) cut the point lights' group
// apart, a plan by kind does not.
Scene directional_point_directional() {
  Scene s = test::load_test_scene("scenes/budget/twelve_mixed.json");
  const Scene d = test::load_test_scene("scenes/budget/eight_directional.json");
  std::vector<Light> points;
  for (const Light& l : s.lights) {
    if (l.type == Light::Type::Point && points.size() < 4) points.push_back(l);
  }
  s.lights = {d.lights[0], d.lights[1]};
  s.lights.insert(s.lights.end(), points.begin(), points.end());
  s.lights.insert(s.lights.end(), {d.lights[2], d.lights[3]});
  return s;
}

size_t planned(const Scene& s, const std::string& profile) {
  return arbfp::plan_passes(s, s.materials.front(), arbfp::parse_variant("pow=mul"), profile)
      .passes.size();
}

TEST(ArbPassSearch, FewestPassesEqualsTheBestPartition) {
  const Scene s = directional_point_directional();
  const size_t best = test::fewest_passes_by_partition(s, "arbfp1-min");
  EXPECT_EQ(planned(s, "arbfp1-min"), best);
  EXPECT_GT(test::consecutive_passes(s, "arbfp1-min"), best)
      << "the case must be one consecutive runs lose (else it shows nothing)";
}

TEST(ArbPassSearch, EveryPlannedPassFitsAndTheCountMeetsTheCapacityBound) {
  for (const char* file : {"scenes/budget/twelve_mixed.json", "scenes/limits/lights64.json"}) {
    const Scene s = test::load_test_scene(file);
    const arbfp::PassPlan plan =
        arbfp::plan_passes(s, s.materials.front(), arbfp::parse_variant("pow=mul"), "ps_2_0");
    EXPECT_GE(plan.passes.size(), plan.lower_bound) << file;
    EXPECT_LE(plan.passes.size(), test::consecutive_passes(s, "ps_2_0")) << file;
    for (const arbfp::Pass& p : plan.passes) {
      EXPECT_TRUE(test::pass_fits(s, p.lights, p.ambient, "ps_2_0")) << file << arbfp::describe(p);
    }
  }
}

// `budget` reports the plan with its capacity bound, and the bound meets the plan on
// twelve_mixed: no pass of 5 of its lights fits ps_2_0, so 12 lights need 3 passes.
TEST(ArbPassSearch, BudgetReportsTheCapacityBound) {
  const auto scene = test::test_scene_path("scenes/budget/twelve_mixed.json").string();
  const test::RunResult r = test::run_ltrender("budget " + scene + " --path arbfp --json");
  EXPECT_EQ(r.exit_code, 1) << r.err;  // the one-pass program is over ps_2_0
  const nlohmann::json j = nlohmann::json::parse(r.out);
  const int most = test::budget_most(j, "most_lights_per_pass");
  const int bound = test::budget_most(j, "capacity_bound");
  ASSERT_GT(most, 0) << j.dump();
  EXPECT_EQ(bound, (12 + most - 1) / most);
  EXPECT_EQ(static_cast<size_t>(bound), test::budget_rows(j, "pass").size())
      << "the plan meets its bound";
  EXPECT_EQ(test::budget_most(j, "passes"), bound);
}

TEST(ArbPassSearch, DescribeNamesRunsOfLights) {
  arbfp::Pass p;
  p.lights = {0, 1, 2, 5, 7, 8};
  p.ambient = true;
  EXPECT_EQ(arbfp::describe(p), "lights 0-2, 5, 7-8 + ambient");
  p.lights = {4};
  p.ambient = false;
  EXPECT_EQ(arbfp::describe(p), "light 4");
}

}  // namespace
}  // namespace lt
