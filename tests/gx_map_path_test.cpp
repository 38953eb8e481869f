// The gx path on scenes whose thickness is a map: the generated program's texture setup
// (GX_TEXMAP1 in the format the map needs, its texgen from the UV, the TEV stage), its counts in
// the budget, the export round trip through `--program`, and the error against the reference
// within a bound derived from the formats' quantisation. The scenes are written here (the
// thickness-map fixtures of map_test_util.h: a UV quad seen head-on, two lights). One process per
// test (GL).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "budget_test_util.h"
#include "load/load_scene.h"
#include "map_test_util.h"
#include "metrics/compare.h"
#include "render/session.h"

namespace lt {
namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// An 8 x 4 map of smooth 8-bit patterns (top row first, as images are written): grey, or each
// channel its own. `ramp`: a coloured 8 x 1 lobe ramp as well.
fs::path write_map_scene(const test::TempDir& dir, bool colour, bool ramp = false) {
  std::vector<float> texels;
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 8; ++x) {
      const double u = (x + 0.5) / 8, v = 1 - (y + 0.5) / 4;
      const double g = 0.15 + 0.8 * u * (0.4 + 0.6 * v);
      if (!colour) {
        texels.push_back(static_cast<float>(std::round(g * 255) / 255));
        continue;
      }
      for (double c : {g, 0.9 - 0.7 * v, 0.2 + 0.5 * u * u})
        texels.push_back(static_cast<float>(std::round(c * 255) / 255));
    }
  }
  test::write_test_image(dir / "map.png", 8, 4, colour ? 3 : 1, texels);
  if (ramp) {
    std::vector<float> r;
    for (int i = 0; i < 8; ++i) {
      const double t = i / 7.0;
      for (double c : {t, t * t, t * t * t})
        r.push_back(static_cast<float>(std::round(c * 255) / 255));
    }
    test::write_test_image(dir / "ramp.png", 8, 1, 3, r);
  }
  test::write_uv_quad(dir.path());
  const fs::path scene = dir / "map.json";
  test::write_file(
      scene, test::map_scene(R"({"texture": "map.png"})", "uv_quad.gltf", ramp ? "ramp.png" : ""));
  return scene;
}

// The grey map is GX_TF_I8; its UV rides after t in
// GX_VA_TEX1, its texgen is GX_TEXCOORD1 through GX_IDENTITY, and stage 1 multiplies it into w.
TEST(GxMapPath, ExportedCSetsUpTheMapInTexmap1) {
  test::TempDir dir;
  const fs::path c = dir / "map.c";
  const test::RunResult r =
      test::run_ltrender("export gx " + write_map_scene(dir, false).string() + " -o " + c.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = read(c);
  for (const char* expected : {
           "static u8 ltrender_thickness_skin[",
           "GX_SetVtxDesc(GX_VA_TEX1, GX_DIRECT);",
           "GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_TEX1, GX_TEX_ST, GX_F32, 0);",
           "GX_SetNumTexGens(2);",
           "GX_SetTexCoordGen(GX_TEXCOORD1, GX_TG_MTX2x4, GX_TG_TEX1, GX_IDENTITY);",
           "GXTexObj thickness;",
           "GX_InitTexObj(&thickness, ltrender_thickness_skin, ",
           ", GX_TF_I8, GX_CLAMP, GX_CLAMP, GX_FALSE);",
           "GX_LoadTexObj(&thickness, GX_TEXMAP1);",
           "GX_SetNumTevStages(4);",
           "GX_SetTevOrder(GX_TEVSTAGE1, GX_TEXCOORD1, GX_TEXMAP1, GX_COLORNULL);",
           "GX_SetTevColorIn(GX_TEVSTAGE1, GX_CC_ZERO, GX_CC_CPREV, GX_CC_TEXC, GX_CC_ZERO);",
           "GX_TexCoord2f32(u, v);",
       }) {
    EXPECT_NE(text.find(expected), std::string::npos) << expected;
  }
}

// A colour map is GX_TF_RGBA8 by default and GX_TF_RGB565 with :map=rgb565, half the bytes.
TEST(GxMapPath, ColourMapIsRgba8OrRgb565) {
  test::TempDir dir;
  const std::string scene = write_map_scene(dir, true).string();
  ASSERT_EQ(test::run_ltrender("export gx " + scene + " -o " + (dir / "a.c").string()).exit_code,
            0);
  ASSERT_EQ(test::run_ltrender("export gx " + scene + " --variant t=vertex:map=rgb565 -o " +
                               (dir / "b.c").string())
                .exit_code,
            0);
  const std::string a = read(dir / "a.c"), b = read(dir / "b.c");
  EXPECT_NE(a.find(", GX_TF_RGBA8, GX_CLAMP, GX_CLAMP, GX_FALSE);"), std::string::npos);
  EXPECT_NE(b.find(", GX_TF_RGB565, GX_CLAMP, GX_CLAMP, GX_FALSE);"), std::string::npos);
  auto bytes = [](const std::string& text) {
    const size_t at = text.find("static u8 ltrender_thickness_skin[");
    EXPECT_NE(at, std::string::npos);
    return std::stol(text.substr(at + std::string("static u8 ltrender_thickness_skin[").size()));
  };
  EXPECT_EQ(bytes(a), 2 * bytes(b));
}

// budget counts the map's stage, texgen and texture map, for the scene and its exported file.
TEST(GxMapPath, BudgetCountsTheMapsStageTexgenAndTexture) {
  test::TempDir dir;
  const std::string scene = write_map_scene(dir, false).string();
  const test::RunResult s = test::run_ltrender("budget " + scene + " --path gx --json");
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const nlohmann::json js = nlohmann::json::parse(s.out);
  EXPECT_EQ(test::budget_most(js, "tev_stages"), 4) << s.out;
  EXPECT_EQ(test::budget_most(js, "texgens"), 2) << s.out;
  EXPECT_EQ(test::budget_most(js, "texture_maps"), 2) << s.out;
  EXPECT_EQ(test::budget_most(js, "vertex_attributes"), 4) << s.out;
  ASSERT_EQ(test::run_ltrender("export gx " + scene + " -o " + (dir / "e.c").string()).exit_code,
            0);
  const test::RunResult f = test::run_ltrender("budget " + (dir / "e.c").string() + " --json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const nlohmann::json jf = nlohmann::json::parse(f.out);
  EXPECT_EQ(test::budget_most(jf, "texture_maps"), 2) << f.out;
  EXPECT_EQ(test::budget_most(jf, "tev_stages"), 4) << f.out;
}

// export, then render --program: the identical image, bit for bit, map and all: grey (I8),
// colour (RGBA8, and RGB565), and a colour map with a colour lobe ramp (the LUT in RGBA8).
TEST(GxMapPath, ExportRoundTripIsBitExact) {
  struct Case {
    bool colour, ramp;
    const char* variant;
  };
  for (const Case& k : {Case{false, false, "t=vertex"}, Case{true, false, "t=vertex"},
                        Case{true, false, "t=vertex:map=rgb565"}, Case{true, true, "t=vertex"},
                        Case{false, false, "t=texgen"}}) {
    test::TempDir dir;
    const fs::path scene_file = write_map_scene(dir, k.colour, k.ramp);
    const Scene scene = load_scene(scene_file);
    const fs::path c = dir / "exported.c";
    const test::RunResult r = test::run_ltrender("export gx " + scene_file.string() +
                                                 " --variant " + k.variant + " -o " + c.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    if (k.ramp) EXPECT_NE(read(c).find(", GX_TF_RGBA8, GX_CLAMP"), std::string::npos);
    const Image generated = render_scene(scene, "gx", k.variant);
    const Image replayed = render_scene(scene, "gx", k.variant, 0, 0, {c.string()});
    ASSERT_EQ(generated.rgba.size(), replayed.rgba.size());
    size_t differ = 0;
    for (size_t i = 0; i < generated.rgba.size(); ++i)
      differ += generated.rgba[i] != replayed.rgba[i];
    EXPECT_EQ(differ, 0u) << k.variant << " colour " << k.colour << " ramp " << k.ramp;
    EXPECT_GT(test::covered_pixels(generated), generated.pixel_count() / 2);
  }
}

// A map of 255 everywhere renders exactly as the constant thickness 1: the map stage's c = 255
// is the TEV's exact pass-through (c' = 256, gx-hardware.md §1.2), and both programs keep a white
// material register and the same light magnitude.
TEST(GxMapPath, AWhiteMapIsExactlyTheConstantThicknessOne) {
  test::TempDir dir;
  test::write_test_image(dir / "white.png", 4, 2, 1, std::vector<float>(8, 1.0f));
  test::write_uv_quad(dir.path());
  test::write_file(dir / "white.json",
                   test::map_scene(R"({"texture": "white.png"})", "uv_quad.gltf"));
  test::write_file(dir / "one.json", test::map_scene("1", "uv_quad.gltf"));
  const Image map = render_scene(load_scene(dir / "white.json"), "gx", "");
  const Image one = render_scene(load_scene(dir / "one.json"), "gx", "");
  ASSERT_EQ(map.rgba.size(), one.rgba.size());
  size_t differ = 0;
  for (size_t i = 0; i < map.rgba.size(); ++i) differ += map.rgba[i] != one.rgba[i];
  EXPECT_EQ(differ, 0u);
  EXPECT_GT(test::covered_pixels(map), map.pixel_count() / 2);
}

// gx against the quad's ground truth (map_test_util.h) on the colour map's quad. On a flat quad
// under an orthographic camera and directional lights t = c0 + k.N is the same at every vertex, so
// per-vertex t costs nothing and what is left is arithmetic: the no-map programs' truncations (XF
// float to int, the material multiply, the interpolated colour: ~0.5 LSB each, downwards, doubled
// where a light needs the x2 scale), plus the map's own: its 7-bit bilinear weights truncated (<
// 1/128 of a texel step, and the >> 14 drops < 1/255 of the texel), and the map stage's product
// rounded (0.5 LSB of w, times the later scales). RGB565 adds the format: a texel moves by up to
// 4/255 (r, b) or 2/255 (g) of T, at most that share of the translucency term (x2 where the pass
// scales it). Bounds: RGBA8 3 truncations of 0.5 doubled by the x2 scale plus the map's 1 LSB,
// 5 max, the downward half of it, 2 mean; RGB565 4 LSB more at most (the format's 4/255 through
// the x2 scale would be 8; the term is below the whole output), 9 max, 2.6 mean. Measured
// 3.96 / 1.59 (RGBA8) and 7.22 / 2.07 (RGB565).
TEST(GxMapPath, ColourMapIsWithinItsFormatsQuantisationOfTheModel) {
  test::TempDir dir;
  const Scene scene = load_scene(write_map_scene(dir, true));
  const Image truth = test::quad_ground_truth(scene);
  const Comparison rgba8 =
      compare_images(render_scene(scene, "gx", ""), truth, TestEncoding::kUnorm8,
                     TestEncoding::kFloat, Coverage::kBoth);
  const Comparison rgb565 =
      compare_images(render_scene(scene, "gx", "t=vertex:map=rgb565"), truth, TestEncoding::kUnorm8,
                     TestEncoding::kFloat, Coverage::kBoth);
  std::printf("gx colour map quad: RGBA8 max %.2f mean %.3f, RGB565 max %.2f mean %.3f LSB\n",
              rgba8.covered.max_lsb, rgba8.covered.mean_lsb, rgb565.covered.max_lsb,
              rgb565.covered.mean_lsb);
  EXPECT_EQ(rgba8.covered.pixels, truth.pixel_count());
  EXPECT_LE(rgba8.covered.max_lsb, 5.0);
  EXPECT_LE(rgba8.covered.mean_lsb, 2.0);
  EXPECT_LE(rgb565.covered.max_lsb, 9.0);
  EXPECT_LE(rgb565.covered.mean_lsb, 2.6);
}

}  // namespace
}  // namespace lt
