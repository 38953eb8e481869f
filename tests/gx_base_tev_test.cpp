// gx `:base=tev` (pass_planner.cpp): a directional light's translucency base as a TEV konst
// colour folded into the LUT stage, COLOR0 the unlit thickness, instead of an XF light whose
// colour is normalised to its largest component and truncated twice on the way
// (docs/advise.md, "What the gx error is made of").
#include <gtest/gtest.h>

#include <cstdio>

#include "image/image.h"
#include "load/load_scene.h"
#include "metrics/compare.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

using gx::GxVariant;

// baked_blob's light 0 (1.4 x (1, 0.9, 0.8), translucency scale 3) on its skin (albedo (0.9,
// 0.78, 0.7), tint (1, 0.3, 0.15), ambient 0.08): (a + s) max(light x albedo x tint) =
// 3.08 x 1.26 = 3.88 needs the x4 scale, so K = light x albedo x tint x 3.08 / 4 =
// (247.4, 57.9, 23.1) / 255: each component rounded once, at full precision.
TEST(GxBaseTev, KonstIsTheBaseRoundedOnceAndColour0IsUnlit) {
  const Scene scene = load_scene(test::source_dir() / "scenes/baked_blob.json");
  const gx::ScenePlan plan = gx::plan_scene(scene, gx::parse_gx_variant("t=vertex:base=tev"));
  ASSERT_EQ(plan.materials.size(), 1u);
  const gx::PassPlan& p = plan.materials[0].passes.at(0);
  ASSERT_TRUE(p.konst_color.has_value());
  EXPECT_EQ(p.figures.translucency_scale, 4);
  EXPECT_EQ(p.konst_color->value, (gx::Color8{247, 58, 23, 255}));
  // REG0 = K a / (a + s) = (6.43, 1.51, 0.60): K's exact value, rounded once.
  ASSERT_TRUE(p.tev_register.has_value());
  EXPECT_EQ(p.tev_register->value, (gx::Color8{6, 2, 1, 255}));
  EXPECT_EQ(p.channels.at(0).enable.name(), std::string("GX_DISABLE"));
  EXPECT_EQ(p.channels.at(0).material_source.name(), std::string("GX_SRC_VTX"));
  // One XF light a vertex (the diffuse) instead of two.
  EXPECT_EQ(p.lights.size(), 1u);
  ASSERT_TRUE(p.stages.at(0).konst_color.has_value());
  EXPECT_EQ(p.stages[0].konst_color->name(), std::string("GX_TEV_KCSEL_K0"));
}

// The XF's truncations of the base are what base=tev removes; measured 3.63 -> 2.59 LSB mean, p99
// 8.20 -> 7.86, on baked_blob at 320x240 (`ltrender render ... --variant t=vertex[:base=tev]`,
// `compare` of the two EXRs). At 128x96 the mean drops as much, but the few pixels where faces
// meet and the console's rasteriser sees the other face are over 1% of the image there and
// decide the p99 (9.25 -> 10.73).
TEST(GxBaseTev, LowersTheMeanErrorOnBakedBlob) {
  const Scene scene = load_scene(test::source_dir() / "scenes/baked_blob.json");
  const Image ref = render_scene(scene, "reference", "", 320, 240);
  const Comparison xf =
      compare_images(render_scene(scene, "gx", "t=vertex", 320, 240), ref, TestEncoding::kUnorm8,
                     TestEncoding::kFloat, Coverage::kBoth);
  const Comparison tev =
      compare_images(render_scene(scene, "gx", "t=vertex:base=tev", 320, 240), ref,
                     TestEncoding::kUnorm8, TestEncoding::kFloat, Coverage::kBoth);
  std::printf("baked_blob mean: base=xf %.3f, base=tev %.3f LSB\n", xf.covered.mean_lsb,
              tev.covered.mean_lsb);
  EXPECT_LT(tev.covered.mean_lsb, xf.covered.mean_lsb - 0.75);
  EXPECT_LT(tev.covered.p99_lsb, xf.covered.p99_lsb);
}

// Point lights attenuate per vertex, so their base stays an XF light: the same image.
TEST(GxBaseTev, PointLightsKeepTheXfBase) {
  const Scene scene = load_scene(test::source_dir() / "scenes/three_point_blob.json");
  const Image tev = render_scene(scene, "gx", "t=vertex:base=tev", 96, 72);
  const Image xf = render_scene(scene, "gx", "t=vertex", 96, 72);
  EXPECT_TRUE(tev.rgba == xf.rgba);
}

TEST(GxBaseTev, VariantSpellingRoundTripsAndXfSpecIsRefused) {
  EXPECT_EQ(gx::to_string(gx::parse_gx_variant("t=vertex:lut=32:base=tev")),
            "t=vertex:lut=32:base=tev");
  EXPECT_EQ(gx::to_string(gx::parse_gx_variant("t=vertex:base=xf")), "t=vertex");
  EXPECT_THROW(gx::parse_gx_variant("lobe=xf-spec:base=tev"), InputError);
  EXPECT_THROW(gx::parse_gx_variant("t=vertex:base=konst"), InputError);
}

}  // namespace
}  // namespace lt
