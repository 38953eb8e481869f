// Issue 10's light packing and pass splitting for the arbfp path: the packed programs meet the
// issue's ALU goals and render like the reference within the arbfp rows of path_bounds.json; a
// scene over ps_2_0 renders in passes whose programs each fit (counted by the counter and by
// Mesa), within a derived bound of the one-pass render; a scene that fits renders byte for byte
// as without a profile; a light that fits no pass is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "arb/arb_ir_counter.h"
#include "arb_ir_query.h"
#include "arb_pass_util.h"
#include "arb_test_util.h"
#include "budget_test_util.h"
#include "load/load_scene.h"
#include "metrics/compare.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_passes.h"
#include "paths/path_bounds.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

budget::ProgramCounts fragment_counts(const Scene& scene, const std::string& variant) {
  const Material& m = scene.materials.front();
  return arbfp::ir::count(
      arbfp::generate_arb(scene, m, arbfp::parse_variant(variant)).fragment_program);
}

// The issue's goals for the default variant, in one ps_2_0 pass (64 ALU, 12 temporaries).
TEST(ArbPacking, ProgramsMeetTheIssuesGoals) {
  struct Goal {
    const char* scene;
    int alu;
  };
  for (const Goal& g :
       {Goal{"scenes/three_point_blob.json", 48}, Goal{"scenes/budget/four_point_lights.json", 56},
        Goal{"scenes/budget/eight_directional.json", 50}}) {
    const budget::ProgramCounts c = fragment_counts(test::load_test_scene(g.scene), "pow=mul");
    EXPECT_LE(c.alu, g.alu) << g.scene;
    EXPECT_LE(c.temporaries, 12) << g.scene;
    EXPECT_LE(c.parameters, 32) << g.scene;
  }
}

// A group of four point lights is packed: its RSQ and RCP run once per light (the scalar
// opcodes), everything else once per group; the colour sums are dot products.
TEST(ArbPacking, FourPointLightsArePackedIntoOneGroup) {
  const Scene scene = test::load_test_scene("scenes/budget/four_point_lights.json");
  const auto p =
      arbfp::generate_arb(scene, scene.materials.front(), arbfp::parse_variant("pow=mul"));
  const auto& fp = p.fragment_program;
  EXPECT_EQ(test::count_op(fp, arbfp::ir::Op::RCP), 4) << "the attenuation, one per light";
  EXPECT_EQ(test::count_op(fp, arbfp::ir::Op::RSQ), 2 + 4) << "N, V and 1/dist per light";
  EXPECT_EQ(test::count_op(fp, arbfp::ir::Op::DP4), 6) << "diffuse and lobe sums, r g b";
  EXPECT_TRUE(test::declares_param(fp, "pos_x0"));
  EXPECT_TRUE(test::declares_param(fp, "color_r0"));
}

// The packed programs against the reference, held to the bounds every demo scene is held to.
TEST(ArbPacking, PackedScenesRenderWithinTheArbfpBounds) {
  for (const char* file :
       {"scenes/budget/four_point_lights.json", "scenes/budget/eight_directional.json"}) {
    const Scene scene = test::load_test_scene(file);
    const Image ref = render_scene(scene, "reference", "", 160, 120);
    for (const char* variant : {"pow=mul", "pow=exact"}) {
      // The arbfp row that applies to a scene without rows of its own (paths/path_bounds.h).
      const PathBound* row = general_path_bound("arbfp", variant);
      ASSERT_NE(row, nullptr) << "no arbfp " << variant << " * row";
      const Image img = render_scene(scene, "arbfp", variant, 160, 120);
      const Comparison c = compare_images(img, ref, TestEncoding::kUnorm8);
      EXPECT_LE(c.covered.max_lsb, row->max_lsb) << file << " " << variant;
      EXPECT_LE(c.covered.mean_lsb, row->mean_lsb) << file << " " << variant;
    }
  }
}

// The hard case of a point light at a mesh vertex, its light four times over: one packed group
// whose every lane needs the distance-0 guard (L = N by CMP in the lanes), against the
// reference within the arbfp bounds.
TEST(ArbPacking, APackedGroupKeepsTheDistanceZeroGuard) {
  Scene scene = test::load_test_scene("scenes/hard/point_light_at_vertex.json");
  ASSERT_EQ(scene.lights.size(), 1u);
  while (scene.lights.size() < 4) scene.lights.push_back(scene.lights.front());
  const auto p =
      arbfp::generate_arb(scene, scene.materials.front(), arbfp::parse_variant("pow=mul"));
  EXPECT_TRUE(test::declares_param(p.fragment_program, "pos_x0")) << "the lights are packed";
  EXPECT_EQ(test::count_op(p.fragment_program, arbfp::ir::Op::CMP), 4) << "L = N, 1/dist = 1";
  const PathBound* row = general_path_bound("arbfp", "pow=mul");
  ASSERT_NE(row, nullptr);
  const Image ref = render_scene(scene, "reference", "", 160, 120);
  const Comparison c =
      compare_images(render_scene(scene, "arbfp", "", 160, 120), ref, TestEncoding::kUnorm8);
  EXPECT_LE(c.covered.max_lsb, row->max_lsb);
  EXPECT_LE(c.covered.mean_lsb, row->mean_lsb);
}

const char kOver[] = "scenes/budget/twelve_mixed.json";

// Every pass of the over-budget scene fits ps_2_0 and vs_2_0, by our counter and by Mesa's
// native counts of the same text; the passes cover every light once and the ambient once.
TEST(ArbPasses, EveryPassFitsTheProfileByTheCounterAndByMesa) {
  const Scene scene = test::load_test_scene(kOver);
  const Material& m = scene.materials.front();
  const arbfp::PowVariant v = arbfp::parse_variant("pow=mul");
  ASSERT_FALSE(
      budget::check(fragment_counts(scene, "pow=mul"), budget::find_profile("ps_2_0")).empty())
      << "the scene must be over ps_2_0 in one pass";
  const arbfp::PassPlan plan = arbfp::plan_passes(scene, m, v, "ps_2_0");
  ASSERT_GE(plan.passes.size(), 2u);
  gl::Context ctx(8, 8);
  std::vector<int> drawn(scene.lights.size(), 0);
  int ambient = 0;
  for (const arbfp::Pass& p : plan.passes) {
    const std::string what = arbfp::describe(p);
    for (size_t i : p.lights) ++drawn[i];
    ambient += p.ambient;
    EXPECT_TRUE(budget::check(p.fragment_counts, budget::find_profile("ps_2_0")).empty()) << what;
    EXPECT_TRUE(budget::check(p.vertex_counts, budget::find_profile("vs_2_0")).empty()) << what;
    test::expect_mesa_counts_agree(p.programs.fragment, p.fragment_counts, what);
  }
  EXPECT_EQ(drawn, std::vector<int>(scene.lights.size(), 1)) << "every light once";
  EXPECT_EQ(ambient, 1);
  EXPECT_TRUE(plan.passes.front().ambient) << "the first pass draws the ambient light";
  // No two passes fit as one.
  for (size_t a = 0; a < plan.passes.size(); ++a) {
    for (size_t b = a + 1; b < plan.passes.size(); ++b) {
      std::vector<size_t> both = plan.passes[a].lights;
      both.insert(both.end(), plan.passes[b].lights.begin(), plan.passes[b].lights.end());
      EXPECT_FALSE(test::pass_fits(scene, both, a == 0, "ps_2_0"))
          << "passes " << a + 1 << " and " << b + 1 << " would fit as one";
    }
  }
}

// The arbfp frame of `scene` into a float target (RGB of every pixel), with or without a
// profile, and the number of passes the path drew.
std::vector<float> float_frame(const Scene& scene, const std::string& profile, int w, int h) {
  RenderSession session(scene, w, h);
  PathOptions o;
  o.profile = profile;
  auto path = session.build(find_path("arbfp"), "pow=mul", o);
  return test::frame_in_float_target(*path, w, h);
}

// In a float target blending adds in float: the passes sum to the one-pass colour up to float
// rounding. The two programs add the same terms in a different order and grouping (each pass
// packs its own lights), so they differ by a few float ulps of the sum: a colour here is below
// 4, whose ulp is 2.4e-7, and 1e-5 allows ~40 of them (0.0026 LSB of 8 bits).
TEST(ArbPasses, PassesSumToTheOnePassRenderInAFloatTarget) {
  const Scene scene = test::load_test_scene(kOver);
  const std::vector<float> one = float_frame(scene, "", 160, 120);
  const std::vector<float> split = float_frame(scene, "ps_2_0", 160, 120);
  ASSERT_EQ(one.size(), split.size());
  double worst = 0;
  size_t lit = 0;
  for (size_t i = 0; i < one.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha: 1 per pass, summed by the blend in a float target
    worst = std::max(worst, static_cast<double>(std::fabs(one[i] - split[i])));
    lit += one[i] > 0.05f;
  }
  EXPECT_GT(lit, one.size() / 20) << "the sphere is lit";
  EXPECT_LE(worst, 1e-5);
}

// In the 8-bit framebuffer each pass is clamped to [0, 1] and rounded to 8 bits before the
// blend adds it (saturating at 1). The contributions are >= 0 (colours, scales, attenuations
// and saturated dot products are), so the clamps compose: min(1, min(1, a) + b) = min(1, a + b)
// for b >= 0, and the one clamp of the one-pass render is matched exactly. The rounding is not:
// N passes round N times, each by at most 0.5 LSB, the one-pass render once, so the two differ
// by at most (N + 1) / 2 LSB, and being whole LSB by at most floor((N + 1) / 2). (The float
// difference above, 0.003 LSB, cannot carry a sum past a further rounding boundary.)
TEST(ArbPasses, PassesAreWithinTheirRoundingOfTheOnePassRenderIn8Bits) {
  const Scene scene = test::load_test_scene(kOver);
  const size_t n =
      arbfp::plan_passes(scene, scene.materials.front(), arbfp::parse_variant("pow=mul"), "ps_2_0")
          .passes.size();
  PathOptions split;
  split.profile = "ps_2_0";
  const Image one = render_scene(scene, "arbfp", "", 160, 120);
  const Image many = render_scene(scene, "arbfp", "", 160, 120, split);
  const double bound = std::floor((static_cast<double>(n) + 1) / 2);
  const Comparison c = compare_images(many, one, TestEncoding::kUnorm8);
  EXPECT_LE(c.image.max_lsb, bound + 1e-9) << n << " passes";
  EXPECT_GT(c.image.max_lsb, 0) << "the passes round on their own (else the test shows nothing)";
}

// A scene that fits one pass: --profile changes nothing, to the byte.
TEST(ArbPasses, AProfileTheSceneFitsChangesNothing) {
  const Scene scene = test::load_test_scene("scenes/three_point_blob.json");
  PathOptions o;
  o.profile = "ps_2_0";
  const Image a = render_scene(scene, "arbfp", "", 96, 72);
  const Image b = render_scene(scene, "arbfp", "", 96, 72, o);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_EQ(a.rgba, b.rgba);
}

// One point light whose t^p alone takes more ALU than arbfp1-min's 48: no pass can hold it.
std::string heavy_light_scene(const test::TempDir& dir) {
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "heavy.json", R"({ "image": { "width": 32, "height": 32 },
  "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0] },
  "materials": { "m": { "albedo": [1, 1, 1],
                        "translucency": { "power": 999999, "normalize_distorted_light": true } } },
  "lights": [ { "type": "point", "position": [0, 0, 2], "color": [1, 1, 1] } ],
  "objects": [ { "mesh": "quad.obj", "material": "m" } ] })");
  return (dir / "heavy.json").string();
}

TEST(ArbPasses, ALightThatFitsNoPassIsRefused) {
  const test::TempDir dir;
  const std::string file = heavy_light_scene(dir);
  const Scene scene = load_scene(file);
  ASSERT_GT(fragment_counts(scene, "pow=mul").alu, 48) << "the light alone must be over";
  EXPECT_THROW(arbfp::plan_passes(scene, scene.materials.front(), arbfp::parse_variant("pow=mul"),
                                  "arbfp1-min"),
               InputError);
  const test::RunResult r = test::run_ltrender(
      "render " + file + " --path arbfp --profile arbfp1-min -o " + (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("light 0 alone does not fit arbfp1-min"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(ArbPassesCli, InfoBudgetAndRenderReportThePasses) {
  const auto scene = test::test_scene_path(kOver).string();
  const test::RunResult info = test::run_ltrender("info " + scene + " --profile ps_2_0");
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("passes to fit ps_2_0"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("pass 2 (lights"), std::string::npos) << info.out;
  const test::RunResult budget = test::run_ltrender("budget " + scene + " --path arbfp --json");
  EXPECT_EQ(budget.exit_code, 1) << budget.err;
  const nlohmann::json j = nlohmann::json::parse(budget.out);
  const std::vector<nlohmann::json> passes = test::budget_rows(j, "pass");
  ASSERT_GE(passes.size(), 2u);
  for (const nlohmann::json& p : passes)
    EXPECT_LE(test::budget_resource(p, "fragment_alu")["used"].get<int>(), 64);
  const test::TempDir dir;
  const test::RunResult glsl = test::run_ltrender(
      "render " + scene + " --path glsl --profile ps_2_0 -o " + (dir / "x.png").string());
  EXPECT_EQ(glsl.exit_code, 2);
  EXPECT_NE(glsl.err.find("takes no profile"), std::string::npos) << glsl.err;
}

}  // namespace
}  // namespace lt
