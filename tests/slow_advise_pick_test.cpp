// `ltrender advise` (docs/advise.md): the pruned search picks what an exhaustive evaluation of
// the same grid picks, checked here by brute force over every rendered candidate, with the hard
// cases rendered again by this test and the pick re-rendered and compared on its own. Labelled
// `slow` in ctest (about 35 s of CPU for the six scene x profile pairs; `ctest -LE slow` skips
// it): every candidate of the arbfp grid is built and rendered.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <string>

#include "advise/advise.h"
#include "advise/hard_cases.h"
#include "advise/target.h"
#include "core/build_paths.h"
#include "load/load_scene.h"
#include "metrics/compare.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::advise {
namespace {

constexpr int kWidth = 48;  // small: the test is about the choice, not the image

// One material of an advised scene: the single material of the demo scenes used below.
constexpr size_t kMaterial = 0;

fs::path advised_demo(const std::string& name) {
  return lt::build_paths::source_dir() / "scenes" / (name + ".json");
}

// True when `variant` renders every hard case the material reaches without a non-finite pixel,
// rendered here by render_scene (not by advise's runner), at the size advise uses.
bool survives_hard_cases(const Target& target, const std::string& variant, const Scene& scene,
                         std::map<std::string, bool>& memo) {
  if (auto it = memo.find(variant); it != memo.end()) return it->second;
  bool ok = true;
  for (const HardCase& hc : reachable_hard_cases(scene, scene.materials[kMaterial])) {
    const Scene hard = load_scene(hc.file);
    if (!target.path->refusal(hard, variant).empty()) continue;
    const Image img = render_scene(hard, target.path->name, variant, std::max(2, hard.width / 2),
                                   std::max(2, hard.height / 2), target.options);
    for (float v : img.rgba) ok = ok && std::isfinite(v);
  }
  return memo[variant] = ok;
}

class AdvisePick : public ::testing::TestWithParam<std::pair<const char*, const char*>> {};

// For budgets of 1, 2 and 4 LSB, max and p99: the pruned search's pick is the cheapest candidate
// of the exhaustive evaluation whose error is within the budget, which renders no non-finite
// pixel on the scene or on a hard case (no cheaper candidate is within the budget), and the
// pick's error, measured again here, is within the budget.
TEST_P(AdvisePick, MatchesTheExhaustiveSearch) {
  const auto [scene_name, profile] = GetParam();
  const Scene scene = load_scene(advised_demo(scene_name));
  ASSERT_EQ(scene.materials.size(), 1u) << "the brute force below is for one material";
  const Target target = find_target(profile);
  AdviseOptions base;
  base.scene_file = advised_demo(scene_name);
  base.profile = profile;
  base.width = kWidth;
  base.exhaustive = true;
  const Advice all = run_advise(base);
  ASSERT_EQ(all.materials.size(), 1u);
  const int height = all.height;
  std::vector<size_t> by_cost(all.candidates.size());
  for (size_t i = 0; i < by_cost.size(); ++i) by_cost[i] = i;
  std::stable_sort(by_cost.begin(), by_cost.end(), [&](size_t a, size_t b) {
    return all.candidates[a].cost[kMaterial] < all.candidates[b].cost[kMaterial];
  });
  std::map<std::string, bool> hard_memo;
  const Image reference = render_scene(scene, "reference", "", kWidth, height);
  int picks = 0;
  for (double budget : {1.0, 2.0, 4.0}) {
    for (Stat stat : {Stat::Max, Stat::P99}) {
      SCOPED_TRACE(std::string(to_string(stat)) + " <= " + std::to_string(budget) + " LSB");
      // Brute force: every rendered candidate, cheapest first.
      std::optional<std::string> expected;
      for (size_t i : by_cost) {
        const CandidateResult& c = all.candidates[i];
        if (!c.rendered || !c.over_profile.empty() || c.non_finite[kMaterial] > 0) continue;
        if (stat_of(c.error[kMaterial], stat) > budget) continue;
        if (!survives_hard_cases(target, c.candidate.variant, scene, hard_memo)) continue;
        expected = c.candidate.variant;
        break;
      }
      AdviseOptions o = base;
      o.exhaustive = false;
      o.max_lsb = budget;
      o.stat = stat;
      const Advice a = run_advise(o);
      const MaterialAdvice& m = a.materials.front();
      ASSERT_EQ(m.pick.has_value(), expected.has_value())
          << (expected ? "exhaustive picks " + *expected : "exhaustive picks nothing");
      if (!expected) {
        // Exit 1 names the closest: the most accurate admissible candidate, over the budget.
        ASSERT_TRUE(m.closest.has_value());
        EXPECT_GT(stat_of(a.candidates[*m.closest].error[kMaterial], stat), budget);
        continue;
      }
      ++picks;
      const std::string& pick = a.candidates[*m.pick].candidate.variant;
      EXPECT_EQ(pick, *expected);
      // The pick measured again, on its own.
      const Image img =
          render_scene(scene, target.path->name, pick, kWidth, height, target.options);
      const Comparison c = compare_images(img, reference, TestEncoding::kUnorm8,
                                          TestEncoding::kFloat, Coverage::kBoth);
      EXPECT_EQ(c.test_non_finite_pixels, 0u);
      EXPECT_LE(stat_of(c.covered, stat), budget) << pick;
      // Fewer candidates rendered than the exhaustive search, and the default always.
      EXPECT_LE(a.rendered(), all.rendered());
      EXPECT_TRUE(a.candidates.front().rendered || !a.candidates.front().over_profile.empty());
    }
  }
  RecordProperty("picks", picks);
}

// baked_blob: per-vertex thickness, p = 4; backlit_sphere: constant thickness. Both one material.
INSTANTIATE_TEST_SUITE_P(DemoScenes, AdvisePick,
                         ::testing::Values(std::pair{"baked_blob", "ps_2_0"},
                                           std::pair{"baked_blob", "gl13-2units"},
                                           std::pair{"baked_blob", "wii-tev"},
                                           std::pair{"backlit_sphere", "ps_2_0"},
                                           std::pair{"backlit_sphere", "gl13-2units"},
                                           std::pair{"backlit_sphere", "wii-tev"}),
                         [](const auto& info) {
                           std::string n = std::string(info.param.first) + "_" + info.param.second;
                           std::replace(n.begin(), n.end(), '-', '_');
                           return n;
                         });

// On baked_blob (p = 4) every LUT program counts fewer instructions than the default pow=mul's
// (measured: 157254 against 193584 operations a frame at 128x96), and a 32- or 64-texel LUT is
// within 2 LSB max: the pick must be cheaper than the default on the work axis.
TEST(Advise, BeatsTheDefaultWhereACheaperVariantFits) {
  AdviseOptions o;
  o.scene_file = advised_demo("baked_blob");
  o.profile = "ps_2_0";
  o.width = kWidth;
  o.max_lsb = 2;
  const Advice a = run_advise(o);
  const MaterialAdvice& m = a.materials.front();
  ASSERT_TRUE(m.pick.has_value());
  EXPECT_LT(a.candidates[*m.pick].cost[m.index].ops, a.candidates.front().cost[m.index].ops);
}

}  // namespace
}  // namespace lt::advise
