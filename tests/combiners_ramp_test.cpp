// Lobe ramps on the combiners path (issue 13): the ramp replaces the power LUT as the lobe's
// table (lobe_table.h: its own texels, 8-bit rgb, read at u = t); a ramp that is the power curve
// renders like the power LUT in every variant within the two tables' 8-bit bounds; an rgb ramp's
// channels land in their channels (the map pass's table included); lobe=cube bakes the ramp, or
// hands an rgb ramp with per-vertex thickness to t=vertex and says so. One process per test (GL).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "gl/context.h"
#include "load/load_scene.h"
#include "map_test_util.h"
#include "metrics/compare.h"
#include "model/texture_sampling.h"
#include "paths/combiners/combiners_path.h"
#include "paths/combiners/lobe_table.h"
#include "ramp_test_util.h"
#include "render/session.h"

namespace lt {
namespace {

const char* const kVariants[] = {"t=vertex", "t=texgen", "lobe=cube"};

// What GL holds of an uploaded table: its internal format and its texels as bytes.
struct Uploaded {
  GLint internal_format = 0;
  std::vector<unsigned char> bytes;
};

Uploaded read_back(const LobeTable& table) {
  const GLuint tex = upload_lobe_table(table);
  glBindTexture(GL_TEXTURE_1D, tex);
  Uploaded u;
  glGetTexLevelParameteriv(GL_TEXTURE_1D, 0, GL_TEXTURE_INTERNAL_FORMAT, &u.internal_format);
  u.bytes.resize(static_cast<size_t>(table.width) * table.channels);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glGetTexImage(GL_TEXTURE_1D, 0, table.channels == 3 ? GL_RGB : GL_LUMINANCE, GL_UNSIGNED_BYTE,
                u.bytes.data());
  glBindTexture(GL_TEXTURE_1D, 0);
  glDeleteTextures(1, &tex);
  return u;
}

std::vector<unsigned char> bytes_of(const std::vector<float>& texels) {
  std::vector<unsigned char> out;
  for (float v : texels) out.push_back(static_cast<unsigned char>(std::lround(v * 255.0)));
  return out;
}

// An 8-bit rgb ramp becomes the table as it is: its texels, rgb, GL_RGB8, read at u = t (no
// remap: the reference reads a ramp at u = t too). A grey one is GL_LUMINANCE8 of its red.
// The map pass's table is (ramp s + a) / (s + a) rounded once; a float ramp brighter than 1 is
// stored divided by its gain, which the constant colour takes.
TEST(CombinersRamp, TableTexelsAreTheRamps8BitTexels) {
  gl::Context ctx(8, 8);
  const auto rgb = test::ramp_8bit(8, [](int i) { return glm::dvec3(i / 7.0, 0.2, 1 - i / 7.0); });
  Translucency tr;
  tr.ramp = rgb;
  tr.ambient = 0.1;
  const LobeTable table = lobe_table(tr);
  EXPECT_EQ(table.width, 8);
  EXPECT_EQ(table.channels, 3);
  EXPECT_EQ(table.coordinate(0.3), 0.3);
  EXPECT_EQ(table.texels, rgb->texture.texels);
  const Uploaded u = read_back(table);
  EXPECT_EQ(u.internal_format, GL_RGB8);
  EXPECT_EQ(u.bytes, bytes_of(rgb->texture.texels));

  Translucency grey;
  grey.ramp = test::ramp_8bit(5, [](int i) { return glm::dvec3(i / 4.0); });
  const LobeTable g = lobe_table(grey);
  EXPECT_EQ(g.channels, 1);
  EXPECT_EQ(read_back(g).internal_format, GL_LUMINANCE8);
  for (int i = 0; i < 5; ++i)
    EXPECT_EQ(g.texels[static_cast<size_t>(i)], grey.ramp->texture.texel(i, 0).r);

  Light light;
  light.translucency_scale = 2;
  const LobeTable map = map_lobe_table(tr, light);
  for (size_t k = 0; k < map.texels.size(); ++k) {
    const double v = (rgb->texture.texels[k] * 2.0 + 0.1) / 2.1;
    EXPECT_EQ(map.texels[k], static_cast<float>(std::round(v * 255) / 255)) << k;
  }

  auto bright = std::make_shared<TextureMap>(*rgb);
  bright->texture.texels = {0, 0, 0, 0.5f, 1, 2};  // two texels, the largest 2
  bright->texture.width = 2;
  Translucency hdr;
  hdr.ramp = bright;
  EXPECT_EQ(lobe_gain(hdr), 2.0);
  const std::vector<float> halved = {0, 0, 0, 64 / 255.0f, 128 / 255.0f, 1};
  EXPECT_EQ(lobe_table(hdr).texels, halved) << "ramp / gain, rounded to 1/255";
}

// A 256-texel ramp of t^8 at its texel centres against the power LUT of t^8 (256 texels at
// t_i = i / 255), through each variant's own program: both tables read the same per-vertex (or
// texgen, or cube) t, so the two renders differ by the tables alone. Each lookup is off t^8 by
// its texel's rounding (0.5/255), linear interpolation (56/8/255^2 = 0.03/255) and llvmpipe's
// 8-bit filtering (< 1/255 below the blend, 8-bit weights: 0.02/255): 1.55/255 each, 3.1/255
// for the two, times the lobe's weight W (albedo * color * s * T over the lights, 1.35 in red)
// carried through 8-bit stages, plus 1 LSB for the two renders' own output rounding. lobe=cube
// bakes both into an 8-bit cube: the curve and the ramp differ by the ramp's rounding and
// interpolation alone (0.53/255 of the lobe) before the cube rounds each once (1 LSB): within the
// same bound.
TEST(CombinersRamp, PowerCurveRampRendersLikeThePowerLut) {
  const Scene curve = test::ortho_sphere(nullptr);
  const Scene ramp = test::ortho_sphere(test::power_ramp(256, 8));
  const glm::dvec3 w = test::lobe_weight(curve);
  const double bound = 3.1 * std::max({w.r, w.g, w.b}) + 1;
  for (const char* variant : kVariants) {
    const Image lut = render_scene(curve, "combiners", variant, 160, 160);
    const Image ramped = render_scene(ramp, "combiners", variant, 160, 160);
    const Comparison c = compare_images(ramped, lut, TestEncoding::kUnorm8);
    std::printf("combiners %s: t^8 ramp against the power LUT %.3f max / %.3f mean LSB\n", variant,
                c.covered.max_lsb, c.covered.mean_lsb);
    EXPECT_GT(c.covered.pixels, lut.pixel_count() / 3) << variant;
    EXPECT_LE(c.covered.max_lsb, bound) << variant;
  }
}

// The coarse ramp on the flat quad (ramp_test_util.h), where t is the same at every vertex and
// pixel: no per-vertex error, so each variant is the reference but for its table. The ramp's
// 8-bit texels are stored exactly; llvmpipe's filtering of them is within 1.05/255 of the blend
// (1/255 from its 8-bit result, its 8-bit weights 0.05/255 of these steps), times the lobe's
// weight W = 1.44, plus the framebuffer's rounding of each of the two passes (0.5 LSB each):
// 2.5 LSB. lobe=cube bakes the ramp (model::sample_ramp) into an 8-bit cube: 0.5 LSB per pass and
// its filtering, within the same bound. A table read at the power LUT's texel-centre remap
// instead of u = t is off by ~29 LSB (ramp_test_util.h).
TEST(CombinersRamp, CoarseRampOnAFlatQuadIsTheReferenceButForItsTable) {
  test::TempDir dir;
  const Scene scene = test::coarse_ramp_quad(dir);
  const Image reference = render_scene(scene, "reference", "");
  for (const char* variant : kVariants) {
    test::expect_coarse_quad_within(scene, reference, "combiners", variant,
                                    1.05 * test::kCoarseQuadLobeWeight + 1);
  }
}

// A pure red ramp against a black one, the translucency ambient 0: the term is ramp * (att T K),
// so only red may differ; green and blue are the same bits in every variant (and in the map
// pass, whose table holds (ramp s + 0) / s).
TEST(CombinersRamp, RedRampLightsOnlyTheRedChannel) {
  for (const char* variant : kVariants) test::expect_red_ramp_lights_only_red("combiners", variant);
  // A thickness map's material: the table of its map pass.
  test::TempDir dir;
  test::write_uv_quad(dir.path());
  test::write_test_image(dir / "map.png", 2, 2, 1, {1, 0.5f, 0.75f, 1});
  test::write_test_image(dir / "red.png", 4, 1, 3, {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0});
  test::write_test_image(dir / "black.png", 4, 1, 3, std::vector<float>(12, 0));
  Image map_images[2];
  for (int k = 0; k < 2; ++k) {
    std::string text = test::map_scene(R"({"texture": "map.png"})", "uv_quad.gltf",
                                       k == 0 ? "red.png" : "black.png");
    text.replace(text.find("\"ambient\": 0.1"), 14, "\"ambient\": 0");
    test::write_file(dir / "s.json", text);
    map_images[k] = render_scene(load_scene(dir / "s.json"), "combiners", "t=vertex");
  }
  test::expect_only_red_differs(map_images[0], map_images[1], 20, "the map pass");
}

// Every variant takes a ramp scene (no refusal). lobe=cube bakes a ramp into the cube: into rgb
// with constant thickness (lobe_cube_full.comb), into the one alpha channel for a grey ramp with
// per-vertex thickness (lobe_cube.comb); an rgb ramp with per-vertex thickness does not fit that
// alpha, so its directional lights take lobe_vertex.comb passes, and `info` says why.
TEST(CombinersRamp, EveryVariantUsesTheRampOrSaysWhy) {
  const PathInfo& combiners = find_path("combiners");
  const Scene demo = test::load_test_scene("scenes/maps/sphere_rgb_ramp.json");
  for (const VariantInfo& v : combiners.variants) {
    EXPECT_TRUE(combiners.refusal(demo, v.name).empty()) << v.name;
  }
  const auto kinds = [](const Scene& s) {
    return plan_combiners(s, CombinersVariant::LobeCube)[0].pass_kinds;
  };
  const Scene constant = test::ortho_sphere(test::flat_ramp({1, 0.5, 0.2}));
  EXPECT_EQ(kinds(constant), std::vector<PassKind>(2, PassKind::LobeCubeFull));

  Scene vertex = test::load_test_scene("scenes/thin_vs_thick.json");
  ASSERT_EQ(vertex.materials.front().translucency->thickness_source, ThicknessSource::Vertex);
  for (Light& l : vertex.lights) l.type = Light::Type::Directional;
  vertex.materials.front().translucency->ramp = test::flat_ramp({0.6, 0.6, 0.6});
  const size_t lights = vertex.lights.size();
  EXPECT_EQ(kinds(vertex), std::vector<PassKind>(lights, PassKind::LobeCube)) << "grey ramp";
  vertex.materials.front().translucency->ramp = test::flat_ramp({1, 0.5, 0.2});
  EXPECT_EQ(kinds(vertex), std::vector<PassKind>(lights, PassKind::LobeVertex)) << "rgb ramp";

  RenderSession session(vertex, 8, 8);
  const auto path = session.build(combiners, "lobe=cube");
  bool said = false;
  for (const BuiltStage& s : path->stages()) {
    said |= s.name.find("rgb lobe ramp with per-vertex thickness") != std::string::npos;
  }
  EXPECT_TRUE(said) << "info says why the cube is not used";
}

}  // namespace
}  // namespace lt
