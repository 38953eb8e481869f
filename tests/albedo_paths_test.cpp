// An albedo map through every path (load/albedo_map.h): a constant map of value a renders
// a x (the image without the map) up to each path's quantisation, with the bound derived from
// the format (not measured and loosened); each path's budget shows the map's cost (one TEX, one
// pass, one TEV stage and texture); what a path cannot take is refused with the scene's key. The
// scene is a 32 x 32 orthographic UV quad with two directional lights whose sums stay below 1 (so
// gx's scales are x1 and no path clamps). One process per test (GL).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "load/load_scene.h"
#include "map_test_util.h"
#include "model/texture_sampling.h"
#include "paths/arbfp/arb_budget.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_budget.h"
#include "render/session.h"

namespace lt {
namespace {

// The map's one sRGB byte, and the linear value it decodes to (IEC 61966-2-1, written out).
constexpr int kByte = 180;
double decoded() {
  return std::pow((kByte / 255.0 + 0.055) / 1.055, 2.4);  // 0.4564
}

std::string scene_text(bool map) {
  return R"({"image": {"width": 32, "height": 32},
  "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "projection": "orthographic", "height": 2},
  "ambient_light": [0.05, 0.05, 0.05],
  "materials": {"skin": {"albedo": [0.9, 0.8, 0.7],)" +
         std::string(map ? R"( "albedo_map": "a.png",)" : "") +
         R"( "translucency": {"power": 2, "distortion": 0.1, "ambient": 0.1, "thickness": 0.6}}},
  "lights": [{"type": "directional", "direction": [0.1, 0.2, 1], "intensity": 0.6,
              "translucency_scale": 0.8},
             {"type": "directional", "direction": [0, 0, -1], "intensity": 0.3}],
  "objects": [{"gltf": "uv_quad.gltf", "material": "skin"}]})";
}

struct Scenes {
  test::TempDir dir;
  Scene with, without;
};
std::unique_ptr<Scenes> write_scenes() {
  auto s = std::make_unique<Scenes>();
  test::write_uv_quad(s->dir.path());
  test::write_test_image(s->dir / "a.png", 4, 4, 3, std::vector<float>(48, kByte / 255.0f));
  test::write_file(s->dir / "with.json", scene_text(true));
  test::write_file(s->dir / "without.json", scene_text(false));
  s->with = load_scene(s->dir / "with.json");
  s->without = load_scene(s->dir / "without.json");
  return s;
}

// Largest |with - a x without| over covered pixels and channels, in LSB of 8 bits.
double worst_lsb(const Image& with, const Image& without, double a) {
  double worst = 0;
  size_t covered = 0;
  for (int y = 0; y < with.height; ++y) {
    for (int x = 0; x < with.width; ++x) {
      if (without.at(x, y)[3] < 0.5f) continue;
      ++covered;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(with.at(x, y)[c] - a * without.at(x, y)[c]) * 255.0);
    }
  }
  EXPECT_EQ(covered, with.pixel_count());
  return worst;
}

// Each path's bound, from what it stores and rounds (LSB of 8 bits; the brightest channel here
// is c <= 0.6, so a relative error e costs at most 0.6 x 255 e):
//  - reference: the texel in float (2^-24 relative), the image in float: 1e-3.
//  - half: h(a), h(a x albedo), h(albedo' x sum) and the unmapped image's own h(albedo x sum):
//    four roundings of 2^-11 relative, 0.6 x 255 x 4 x 2^-11 = 0.30.
//  - glsl, arbfp: both images rounded to 8 bits (0.5 for the mapped one, a x 0.5 for the other)
//    and the GL_RGB16F texel (2^-11 relative, 0.6 x 255 x 2^-11 = 0.075): 0.5 + 0.5 a + 0.075.
//  - combiners: the blend multiplies the unmapped image's bytes F by the GL_RGB8 texel A / 255:
//    its rounding (at most 1, GL does not require round-to-nearest) and the texel's (F x 0.5 /
//    255 <= 0.5): 1.5.
//  - gx (scales x1 here): the unmapped image is trans + COLOR1, integers; the mapped one
//    round(trans c' / 256) + round(COLOR1 c' / 256), each lerp (x c' + 128) >> 8 with
//    c' = A + (A >> 7) [HWT gxtest/tev.cpp L16-36]: two roundings (1.0), c' / 256 against
//    A / 255 ((trans + COLOR1) (255 - A) / 65280 <= 0.45) and the texel's 8 bits (0.5): 1.95.
TEST(AlbedoPaths, ConstantMapScalesTheImageWithinEachFormatsQuantisation) {
  const auto s = write_scenes();
  const double a = decoded();
  struct Case {
    const char* path;
    double bound;
  };
  for (const Case& k :
       {Case{"reference", 1e-3}, Case{"half", 0.30}, Case{"glsl", 0.5 + 0.5 * a + 0.075},
        Case{"arbfp", 0.5 + 0.5 * a + 0.075}, Case{"combiners", 1.5}, Case{"gx", 1.95}}) {
    const Image with = render_scene(s->with, k.path, "");
    const Image without = render_scene(s->without, k.path, "");
    const double worst = worst_lsb(with, without, a);
    std::printf("%-9s |with - a without| max %.4f LSB (bound %.4f)\n", k.path, worst, k.bound);
    EXPECT_LE(worst, k.bound) << k.path;
  }
}

// The cost, in each path's own budget: arbfp one TEX and one ALU (the MUL by the albedo) in the
// fragment program, one MOV of the UVs in the vertex program, no texture indirection; combiners
// one pass more (albedo_modulate.comb, one stage, one unit); gx one TEV stage (trans x map; the
// last stage reads the map too), one texgen and one texture map more in every pass with a
// translucency stage (a diffuse-only pass: texgen and map, no stage).
TEST(AlbedoPaths, EveryBudgetCountsTheMap) {
  const auto s = write_scenes();
  auto arb = [](const Scene& scene, const char* kind) {
    const budget::Report r = budget::run_budget(scene, "", "ps_2_0");
    for (const budget::Item& p : r.items) {
      if (p.scope == budget::Scope::Program && p.name.find(kind) != std::string::npos) return p;
    }
    ADD_FAILURE() << "no " << kind;
    return budget::Item{};
  };
  const budget::Item f1 = arb(s->with, "fragment"), f0 = arb(s->without, "fragment");
  EXPECT_EQ(f1.used("tex"), f0.used("tex") + 1);
  EXPECT_EQ(f1.used("alu"), f0.used("alu") + 1);
  EXPECT_EQ(f1.used("indirections"), f0.used("indirections"));
  EXPECT_EQ(arb(s->with, "vertex").used("alu"), arb(s->without, "vertex").used("alu") + 1);

  const budget::Report c1 = combiner_budget(s->with, "gl13-2units");
  const budget::Report c0 = combiner_budget(s->without, "gl13-2units");
  EXPECT_EQ(c1.most("passes"), c0.most("passes") + 1);
  EXPECT_EQ(c1.most("texture_units"), c0.most("texture_units"));  // the modulate pass: one stage
  EXPECT_NE(c1.items.at(0).program.find("albedo_modulate.comb"), std::string::npos);
  EXPECT_TRUE(c1.fits());

  const budget::Report g1 = gx::gx_budget_scene(s->with, "", "wii-tev");
  const budget::Report g0 = gx::gx_budget_scene(s->without, "", "wii-tev");
  ASSERT_EQ(g1.items.size(), g0.items.size());
  for (size_t i = 0; i < g1.items.size(); ++i) {
    if (g1.items[i].scope != budget::Scope::Pass) continue;
    const budget::Item &a = g1.items[i], &b = g0.items[i];
    EXPECT_EQ(a.used("tev_stages"), b.used("tev_stages") + 1) << i;
    EXPECT_EQ(a.used("texgens"), b.used("texgens") + 1) << i;
    EXPECT_EQ(a.used("texture_maps"), b.used("texture_maps") + 1) << i;
  }
}

std::string render_refusal(const Scene& scene, const char* path) {
  try {
    render_scene(scene, path, "");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(rendered)";
}

// arbfp: the albedo map's UVs and a vertex thickness would share texcoord[2] (the generator
// refuses before any vertex colour is read).
TEST(AlbedoPaths, ArbfpRefusesVertexThicknessWithAnAlbedoMap) {
  const auto s = write_scenes();
  Scene vertex = s->with;
  vertex.materials[0].translucency->thickness_source = ThicknessSource::Vertex;
  const std::string why = render_refusal(vertex, "arbfp");
  EXPECT_NE(why.find("materials.skin.albedo_map: arbfp"), std::string::npos) << why;
}

// gx: repeat and mirror need power-of-two sides [OGC gx.h L4287-4288], so a 5 x 4 map that
// repeats along s is resampled to 8 x 4 (the array's comment says so) and renders; texels over
// 1 have no GX texture format and are refused with the scene's key.
TEST(AlbedoPaths, GxResamplesARepeatingMapToPowerOfTwoAndRefusesTexelsOverOne) {
  const auto s = write_scenes();
  auto map = std::make_shared<TextureMap>(*s->with.materials[0].albedo_map);
  map->texture.width = 5;
  map->texture.texels.assign(5 * 4 * 3, 0.5f);
  map->texture.wrap_s = model::Wrap::Repeat;
  Scene repeat = s->with;
  repeat.materials[0].albedo_map = map;
  const gx::GeneratedPrograms g = gx::generate_programs(repeat, gx::GxVariant{});
  std::string comment;
  for (const gx::Statement& st : g.file.top_level) {
    if (st.kind == gx::Statement::Kind::Declaration &&
        st.declaration.name == "ltrender_albedo_skin")
      comment = st.comment;
  }
  EXPECT_NE(comment.find("8x4 texels"), std::string::npos) << comment;
  EXPECT_NE(comment.find("Resampled bilinearly from the map's 5x4"), std::string::npos) << comment;
  EXPECT_EQ(render_scene(repeat, "gx", "").width, 32);

  auto bright = std::make_shared<TextureMap>(*s->with.materials[0].albedo_map);
  bright->texture.texels[0] = 1.5f;
  Scene over = s->with;
  over.materials[0].albedo_map = bright;
  const std::string over_why = render_refusal(over, "gx");
  EXPECT_NE(over_why.find("materials.skin.albedo_map: gx: the albedo map holds values up to 1.5"),
            std::string::npos)
      << over_why;
}

}  // namespace
}  // namespace lt
