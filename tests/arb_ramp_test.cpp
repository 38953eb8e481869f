// Lobe ramps on the arbfp path (issue 13): every variant reads the ramp instead of computing t^p
// (one TEX per light of texture[0]); a ramp that is the power curve renders like the power LUT
// and like the reference within the tables' 8-bit bounds; an rgb ramp's channels land in their
// channels; the budget counts the ramp's TEX, as Mesa does; --profile still splits a ramp scene
// into passes that fit. One process per test (GL).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "metrics/compare.h"
#include "paths/arbfp/arb_budget.h"
#include "paths/arbfp/arb_generator.h"
#include "arb/arb_ir_counter.h"
#include "paths/arbfp/arb_passes.h"
#include "ramp_test_util.h"
#include "render/session.h"

namespace lt {
namespace {

const char kRampScene[] = "scenes/maps/sphere_rgb_ramp.json";

// No variant refuses the demo ramp scene, and each renders it: finite and lit. Every variant
// but pow=mul:vertex generates the same program on a ramp material (the ramp is the curve: the
// variants differ only in how they approximate t^p), so their images are pow=mul's, bit for bit;
// pow=mul:vertex interpolates t per vertex and differs.
TEST(ArbfpRamp, EveryVariantRendersTheRampScene) {
  const Scene scene = test::load_test_scene(kRampScene);
  const PathInfo& arbfp = find_path("arbfp");
  const Image mul = render_scene(scene, "arbfp", "pow=mul", 160, 120);
  EXPECT_GT(test::covered_pixels(mul), mul.pixel_count() / 10);
  for (const VariantInfo& v : arbfp.variants) {
    ASSERT_TRUE(arbfp.refusal(scene, v.name).empty()) << v.name;
    const Image img = render_scene(scene, "arbfp", v.name, 160, 120);
    EXPECT_EQ(test::non_finite(img), 0u) << v.name;
    if (arbfp::parse_variant(v.name).per_vertex) {
      EXPECT_NE(img.rgba, mul.rgba) << v.name << ": t per vertex";
    } else {
      EXPECT_EQ(img.rgba, mul.rgba) << v.name << " reads the ramp as pow=mul does";
    }
  }
}

// A 256-texel ramp of t^8 at its texel centres against t^8 itself. Each table lookup is off the
// curve by its texel's rounding (0.5/255), linear interpolation (h^2/8 max f'' = 56/8/255^2 =
// 0.03/255) and llvmpipe's filtering of 8-bit texels, whose result is an 8-bit value again (up
// to 1/255 below the blend) with 8-bit weights (a texel step, at most 8/255 here, over 512:
// 0.02/255): 1.55/255 in all. Times the lobe's weight W (albedo * color * s * T summed over the
// lights) that is at most 1.55 W LSB, plus the output's rounding: 0.5 LSB against the
// reference (exact t^8), 1 LSB against the power LUT's render, which has the same error budget
// of its own (2 x 1.55 W). W = 1.35 in red here.
TEST(ArbfpRamp, PowerCurveRampRendersLikeThePowerLut) {
  const Scene curve = test::ortho_sphere(nullptr);
  const Scene ramp = test::ortho_sphere(test::power_ramp(256, 8));
  const glm::dvec3 w = test::lobe_weight(curve);
  const double weight = std::max({w.r, w.g, w.b});
  const double lookup = 1.55;  // LSB of the lobe per lookup, above
  const Image reference = render_scene(curve, "reference", "", 160, 160);
  const Image lut = render_scene(curve, "arbfp", "pow=lut:256:u8", 160, 160);
  const Image ramped = render_scene(ramp, "arbfp", "pow=mul", 160, 160);
  const Comparison to_lut = compare_images(ramped, lut, TestEncoding::kUnorm8);
  const Comparison to_reference = compare_images(ramped, reference, TestEncoding::kUnorm8);
  std::printf(
      "t^8 ramp: against pow=lut:256:u8 %.3f max / %.3f mean, against the reference "
      "%.3f / %.3f LSB (W %.3f)\n",
      to_lut.covered.max_lsb, to_lut.covered.mean_lsb, to_reference.covered.max_lsb,
      to_reference.covered.mean_lsb, weight);
  EXPECT_GT(to_reference.covered.pixels, reference.pixel_count() / 3);
  EXPECT_LE(to_reference.covered.max_lsb, lookup * weight + 0.5);
  EXPECT_LE(to_lut.covered.max_lsb, 2 * lookup * weight + 1);
}

// The coarse ramp on the flat quad (ramp_test_util.h), where t is the same at every vertex and
// pixel (so pow=mul:vertex is exact too): the reference but for the ramp's lookup, within
// llvmpipe's 8-bit filtering of the exactly stored texels (1.05/255 of the blend) times the
// lobe's weight 1.44, and the output's rounding (0.5 LSB). A lookup at the power LUT's remap
// instead of (t, t) would be ~29 LSB off.
TEST(ArbfpRamp, CoarseRampOnAFlatQuadIsTheReferenceButForItsLookup) {
  test::TempDir dir;
  const Scene scene = test::coarse_ramp_quad(dir);
  const Image reference = render_scene(scene, "reference", "");
  for (const char* variant : {"pow=mul", "pow=lut:16:u8", "pow=mul:vertex"}) {
    test::expect_coarse_quad_within(scene, reference, "arbfp", variant,
                                    1.05 * test::kCoarseQuadLobeWeight + 0.5);
  }
}

// A pure red ramp and a black one, with the translucency ambient 0: the translucency term is
// (ramp * s) * T, so the two images may differ in red only, and green and blue are the same bits
// (the same program, the same diffuse), in every variant of the fragment lobe and per vertex.
TEST(ArbfpRamp, RedRampLightsOnlyTheRedChannel) {
  for (const char* variant : {"pow=mul", "pow=lut:256:u8", "pow=mul:vertex"}) {
    test::expect_red_ramp_lights_only_red("arbfp", variant);
  }
}

// The ramp's TEX are counted: on the demo ramp scene (a thickness map and two lights) every
// variant's fragment program has 1 + 2 TEX in two indirections (the map's TEX reads an input,
// the ramp's read the computed t), and Mesa's native counts of the same text agree on ALU, TEX
// and temporaries. The budget's term cost gives each light its ramp TEX (and the first light the
// map's, which only the term reads).
TEST(ArbfpRamp, BudgetCountsOneTexPerLightAndMesaAgrees) {
  const Scene scene = test::load_test_scene(kRampScene);
  const Material& m = scene.materials.front();
  ASSERT_EQ(scene.lights.size(), 2u);
  gl::Context ctx(8, 8);
  for (const VariantInfo& v : find_path("arbfp").variants) {
    const auto p = arbfp::generate_arb(scene, m, arbfp::parse_variant(v.name));
    const budget::ProgramCounts c = arbfp::ir::count(p.fragment_program);
    EXPECT_EQ(c.tex, 3) << v.name;
    EXPECT_EQ(c.indirections, 2) << v.name;
    EXPECT_FALSE(p.lut.has_value()) << v.name << ": the ramp is the table";
    test::expect_mesa_counts_agree(p.fragment, c, v.name);
    const budget::Report r = budget::run_budget(scene, v.name, "ps_2_0");
    EXPECT_TRUE(r.fits()) << v.name << ": " << r.first_overrun();
    const std::vector<budget::TermCost> costs = budget::term_costs(scene, v.name);
    ASSERT_EQ(costs.size(), 1u);
    const auto& per_light = costs[0].per_light;
    ASSERT_EQ(per_light.size(), 2u);
    EXPECT_EQ(per_light[0].tex, 2) << v.name << ": the map's TEX (only the term reads T), a ramp's";
    EXPECT_EQ(per_light[1].tex, 1) << v.name << ": the ramp's";
  }
}

// scenes/budget/twelve_mixed.json with a ramp is over ps_2_0 in one pass: --profile splits it
// into passes whose programs fit by the counter and by Mesa, each with one ramp TEX per light of
// its own, and in a float target the passes sum to the one-pass render (as without a ramp,
// arb_pass_test: 1e-5 is ~40 float ulps of a colour below 4).
TEST(ArbfpRamp, ProfileSplitsARampSceneIntoPassesThatFit) {
  Scene scene = test::load_test_scene("scenes/budget/twelve_mixed.json");
  scene.materials.front().translucency->ramp =
      test::ramp_8bit(16, [](int i) { return glm::dvec3(i / 15.0, (i / 15.0) * (i / 15.0), 0.3); });
  const Material& m = scene.materials.front();
  const arbfp::PowVariant v = arbfp::parse_variant("pow=mul");
  const arbfp::PassPlan plan = arbfp::plan_passes(scene, m, v, "ps_2_0");
  ASSERT_GE(plan.passes.size(), 2u);
  gl::Context ctx(8, 8);
  for (const arbfp::Pass& p : plan.passes) {
    const std::string what = arbfp::describe(p);
    EXPECT_TRUE(budget::check(p.fragment_counts, budget::find_profile("ps_2_0")).empty()) << what;
    EXPECT_EQ(p.fragment_counts.tex, static_cast<int>(p.lights.size())) << what;
    test::expect_mesa_counts_agree(p.programs.fragment, p.fragment_counts, what);
  }
  const auto float_frame = [&](const std::string& profile) {
    RenderSession session(scene, 160, 120);
    PathOptions o;
    o.profile = profile;
    auto path = session.build(find_path("arbfp"), "pow=mul", o);
    return test::frame_in_float_target(*path, 160, 120);
  };
  const std::vector<float> one = float_frame(""), split = float_frame("ps_2_0");
  ASSERT_EQ(one.size(), split.size());
  double worst = 0;
  size_t lit = 0;
  for (size_t i = 0; i < one.size(); ++i) {
    if (i % 4 == 3) continue;  // alpha: 1 per pass, summed by the blend
    worst = std::max(worst, static_cast<double>(std::fabs(one[i] - split[i])));
    lit += one[i] > 0.05f;
  }
  EXPECT_GT(lit, one.size() / 20);
  EXPECT_LE(worst, 1e-5);
}

}  // namespace
}  // namespace lt
