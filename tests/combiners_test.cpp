// The combiners path (issue 5): the combiner-program format (good and bad files, errors with file
// and line), the GL state a program produces, the path against the reference with thresholds
// that follow from per-vertex evaluation, error against tessellation, and stage budgets.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <nlohmann/json.hpp>

#include "combiner/combiner_program.h"
#include "core/error.h"
#include "gl/context.h"
#include "load/load_scene.h"
#include "metrics/compare.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/combiners/combiners_path.h"
#include "paths/combiners/texgen_matrix.h"
#include "render/session.h"
#include "scene/scene_parse.h"
#include "test_util.h"

namespace lt {
namespace {

namespace fs = std::filesystem;
using combiners::CombinerProgram;
using combiners::Function;
using combiners::Operand;
using combiners::Source;

// ---------------------------------------------------------------------------------------------
// Format

TEST(CombinerFormat, ShippedProgramsParse) {
  for (const char* name : {"lobe_vertex.comb", "lobe_texgen.comb", "diffuse_only.comb"}) {
    EXPECT_NO_THROW(combiners::load_combiner_program(name)) << name;
  }
}

TEST(CombinerFormat, LobeProgramIsTwoStagesAndColourSum) {
  const CombinerProgram p = combiners::load_combiner_program("lobe_vertex.comb");
  EXPECT_EQ(p.name, "lobe_vertex");
  EXPECT_TRUE(p.color_sum);
  ASSERT_EQ(p.stages.size(), 2u);
  const auto& s0 = p.stages[0];
  EXPECT_EQ(s0.texture, "power_lut");
  EXPECT_EQ(s0.texcoord, combiners::TexCoord::Array);
  EXPECT_EQ(s0.rgb.function, Function::Modulate);
  ASSERT_EQ(s0.rgb.args.size(), 2u);
  EXPECT_EQ(s0.rgb.args[0].source, Source::Texture);
  EXPECT_EQ(s0.rgb.args[1].source, Source::Primary);
  EXPECT_EQ(s0.alpha.args[0].operand, Operand::Alpha);
  const auto& s1 = p.stages[1];
  EXPECT_EQ(s1.texture, "white");
  EXPECT_EQ(s1.rgb.scale, 0) << "fit";
  EXPECT_EQ(s1.constant_name, "lobe_color");
  // Alpha defaults to REPLACE previous.alpha when a stage does not say.
  EXPECT_EQ(s1.alpha.function, Function::Replace);
  EXPECT_EQ(s1.alpha.args[0].source, Source::Previous);
  EXPECT_EQ(p.constant_colors(), 1);
}

TEST(CombinerFormat, EveryFunctionSourceAndOperandParses) {
  const std::string text =
      "# all of it\n"
      "program everything\n"
      "color_sum off\n"
      "stage 0\n"
      "  texture power_lut\n"
      "  texcoord array\n"
      "  rgb INTERPOLATE texture 1-primary constant.alpha\n"
      "  alpha ADD_SIGNED texture 1-previous  # comment after\n"
      "  rgb_scale 2\n"
      "  alpha_scale 4\n"
      "  constant 0.5 0.25 1 0\n"
      "stage 1\n"
      "  texture lobe_cube\n"
      "  texcoord normal_map\n"
      "  rgb DOT3_RGBA texture0 1-texture1.alpha\n"
      "stage 2\n"
      "  texture white\n"
      "  rgb SUBTRACT previous texture0.color\n"
      "  alpha MODULATE primary constant\n";
  const CombinerProgram p = combiners::parse_combiner_program(text, "all.comb");
  ASSERT_EQ(p.stages.size(), 3u);
  EXPECT_EQ(p.stages[0].rgb.function, Function::Interpolate);
  EXPECT_EQ(p.stages[0].rgb.args[1].operand, Operand::OneMinusColor);
  EXPECT_EQ(p.stages[0].rgb.args[2].operand, Operand::Alpha);
  EXPECT_EQ(p.stages[0].alpha.args[1].operand, Operand::OneMinusAlpha);
  EXPECT_EQ(p.stages[0].rgb.scale, 2);
  EXPECT_EQ(p.stages[0].alpha.scale, 4);
  EXPECT_EQ(p.stages[0].constant, glm::dvec4(0.5, 0.25, 1, 0));
  EXPECT_EQ(p.stages[1].rgb.args[0].source, Source::TextureUnit);
  EXPECT_EQ(p.stages[1].rgb.args[1].unit, 1);
  EXPECT_EQ(p.stages[1].rgb.args[1].operand, Operand::OneMinusAlpha);
  EXPECT_EQ(p.stages[2].rgb.args[1].operand, Operand::Color);
}

// A program saved by a Windows editor, with a UTF-8 byte-order mark first, is the same program.
TEST(CombinerFormat, AByteOrderMarkBeforeTheProgramIsSkipped) {
  const std::string text = "stage 0\n  rgb MODULATE primary previous\n";
  const CombinerProgram plain = combiners::parse_combiner_program(text, "plain.comb");
  const CombinerProgram marked =
      combiners::parse_combiner_program("\xEF\xBB\xBF" + text, "marked.comb");
  ASSERT_EQ(marked.stages.size(), 1u);
  EXPECT_EQ(marked.stages[0].rgb.function, plain.stages[0].rgb.function);
  EXPECT_EQ(marked.stages[0].rgb.args[0].source, plain.stages[0].rgb.args[0].source);
  EXPECT_EQ(marked.stages[0].rgb.args[1].source, plain.stages[0].rgb.args[1].source);
}

struct BadProgram {
  const char* label;
  std::string text;
  int line;
  const char* message;  // a substring of the error
};

const BadProgram kBad[] = {
    {"empty", "# nothing\n", 1, "no stages"},
    {"outside_stage", "rgb REPLACE primary\n", 1, "outside a stage"},
    {"unknown_directive", "stage 0\n  rgb REPLACE primary\n  colour red\n", 3,
     "unknown directive 'colour'"},
    {"unknown_function", "stage 0\n\n  rgb MULTIPLY primary previous\n", 3,
     "unknown function 'MULTIPLY'"},
    {"argument_count", "stage 0\n  rgb MODULATE primary\n", 2, "MODULATE takes 2 arguments"},
    {"unknown_source", "stage 0\n  rgb REPLACE secondary\n", 2, "unknown source 'secondary'"},
    {"colour_in_alpha", "stage 0\n  rgb REPLACE primary\n  alpha REPLACE primary.color\n", 3,
     "operand must be .alpha"},
    {"dot3_alpha", "stage 0\n  rgb REPLACE primary\n  alpha DOT3_RGB primary primary\n", 3,
     "rgb function"},
    {"bad_scale", "stage 0\n  rgb REPLACE primary\n  rgb_scale 3\n", 3, "1, 2 or 4"},
    {"stage_order", "stage 0\n  rgb REPLACE primary\nstage 2\n  rgb REPLACE previous\n", 3,
     "out of order"},
    {"missing_rgb", "stage 0\n  texture white\nstage 1\n  rgb REPLACE previous\n", 1,
     "no `rgb` function"},
    {"texture_not_bound", "stage 0\n  rgb MODULATE texture primary\n", 1, "binds none"},
    {"crossbar_to_nothing",
     "stage 0\n  texture white\n  rgb REPLACE primary\nstage 1\n  texture white\n"
     "  rgb MODULATE previous texture3\n",
     4, "no unit 3"},
    {"crossbar_to_untextured",
     "stage 0\n  rgb REPLACE primary\nstage 1\n  texture white\n  rgb MODULATE texture0 previous\n",
     3, "unit 0 binds no texture"},
    {"texture_not_a_name", "stage 0\n  texture mar-ble\n  rgb REPLACE texture\n", 2,
     "is not a name"},
    {"duplicate", "stage 0\n  rgb REPLACE primary\n  rgb REPLACE previous\n", 3, "given twice"},
    {"literal_out_of_range", "stage 0\n  rgb REPLACE constant\n  constant 2 0 0 1\n", 3,
     "outside [0, 1]"},
    // NaN passed the range check (NaN < 0 and NaN > 1 are false).
    {"literal_nan", "stage 0\n  rgb REPLACE constant\n  constant nan 0 0 0\n", 3,
     "'nan' is not a finite number"},
    {"literal_inf", "stage 0\n  rgb REPLACE constant\n  constant 0 -inf 0 0\n", 3,
     "'-inf' is not a finite number"},
    {"fit_without_name", "stage 0\n  rgb REPLACE constant\n  rgb_scale fit\n", 1,
     "needs a named constant"},
    {"too_many_stages",
     "stage 0\n rgb REPLACE primary\nstage 1\n rgb REPLACE primary\nstage 2\n rgb REPLACE "
     "primary\nstage 3\n rgb REPLACE primary\nstage 4\n rgb REPLACE primary\nstage 5\n rgb "
     "REPLACE primary\nstage 6\n rgb REPLACE primary\nstage 7\n rgb REPLACE primary\nstage 8\n",
     17, "at most 8"},
};

class BadCombinerProgram : public ::testing::TestWithParam<BadProgram> {};

TEST_P(BadCombinerProgram, NamesFileAndLine) {
  const BadProgram& b = GetParam();
  try {
    combiners::parse_combiner_program(b.text, "bad.comb");
    FAIL() << "parsed without error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.comb");
    EXPECT_EQ(e.where(), std::to_string(b.line)) << e.what();
    EXPECT_NE(e.what_only().find(b.message), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Format, BadCombinerProgram, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return std::string(info.param.label); });

TEST(CombinerFormat, FitScaleIsTheSmallestThatShowsTheConstant) {
  EXPECT_EQ(combiners::fit_scale(0.0), 1);
  EXPECT_EQ(combiners::fit_scale(1.0), 1);
  EXPECT_EQ(combiners::fit_scale(1.01), 2);
  EXPECT_EQ(combiners::fit_scale(4.0), 4);
  EXPECT_EQ(combiners::fit_scale(9.0), 4);
}

// ---------------------------------------------------------------------------------------------
// GL state

GLint env(GLenum unit, GLenum pname) {
  glActiveTexture(unit);
  GLint v = -1;
  glGetTexEnviv(GL_TEXTURE_ENV, pname, &v);
  return v;
}

TEST(CombinerState, LobeProgramSetsTheTexEnvItSays) {
  gl::Context ctx(8, 8);
  GLuint tex[2];
  glGenTextures(2, tex);
  combiners::ProgramInputs in;
  in.textures["power_lut"] = {GL_TEXTURE_1D, tex[0]};
  in.textures["white"] = {GL_TEXTURE_2D, tex[1]};
  in.constants["lobe_color"] = glm::dvec4(2.4, 1.2, 0.6, 1);  // needs scale 4 (2.4 > 2)
  const auto applied = combiners::apply(combiners::load_combiner_program("lobe_vertex.comb"), in);
  ASSERT_EQ(applied.size(), 2u);
  EXPECT_EQ(env(GL_TEXTURE0, GL_TEXTURE_ENV_MODE), GL_COMBINE);
  EXPECT_EQ(env(GL_TEXTURE0, GL_COMBINE_RGB), GL_MODULATE);
  EXPECT_EQ(env(GL_TEXTURE0, GL_SRC0_RGB), GL_TEXTURE);
  EXPECT_EQ(env(GL_TEXTURE0, GL_SRC1_RGB), GL_PRIMARY_COLOR);
  EXPECT_EQ(env(GL_TEXTURE0, GL_OPERAND0_RGB), GL_SRC_COLOR);
  EXPECT_EQ(env(GL_TEXTURE0, GL_COMBINE_ALPHA), GL_REPLACE);
  EXPECT_EQ(env(GL_TEXTURE0, GL_SRC0_ALPHA), GL_PRIMARY_COLOR);
  EXPECT_EQ(env(GL_TEXTURE1, GL_COMBINE_RGB), GL_MODULATE);
  EXPECT_EQ(env(GL_TEXTURE1, GL_SRC0_RGB), GL_PREVIOUS);
  EXPECT_EQ(env(GL_TEXTURE1, GL_SRC1_RGB), GL_CONSTANT);
  EXPECT_EQ(env(GL_TEXTURE1, GL_SRC0_ALPHA), GL_PREVIOUS);
  EXPECT_EQ(env(GL_TEXTURE2, GL_TEXTURE_ENV_MODE), GL_MODULATE) << "units above are reset";
  glActiveTexture(GL_TEXTURE1);
  GLfloat scale = 0, color[4] = {};
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_RGB_SCALE, &scale);
  glGetTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, color);
  EXPECT_EQ(scale, 4.0f);
  EXPECT_FLOAT_EQ(color[0], 0.6f);
  EXPECT_FLOAT_EQ(color[1], 0.3f);
  EXPECT_FLOAT_EQ(color[2], 0.15f);
  EXPECT_FALSE(applied[1].constant_clamped);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_2D));  // unit 1 binds white (2D) so its stage runs
  EXPECT_FALSE(glIsEnabled(GL_TEXTURE_1D));
  glActiveTexture(GL_TEXTURE0);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_1D));
  EXPECT_TRUE(glIsEnabled(GL_COLOR_SUM));
  combiners::reset_texture_state(combiners::kMaxStages);
  EXPECT_FALSE(glIsEnabled(GL_COLOR_SUM));
  EXPECT_EQ(env(GL_TEXTURE0, GL_TEXTURE_ENV_MODE), GL_MODULATE);
  gl::check_error("combiner state test");
  glDeleteTextures(2, tex);
}

TEST(CombinerState, CrossbarAndTexgenState) {
  gl::Context ctx(8, 8);
  GLuint tex = 0;
  glGenTextures(1, &tex);
  const CombinerProgram p = combiners::parse_combiner_program(
      "stage 0\n texture lobe_cube\n texcoord normal_map\n rgb REPLACE texture\n"
      "stage 1\n texture lobe_cube\n rgb ADD previous texture0.alpha\n constant 0 0.5 1 1\n",
      "x.comb");
  combiners::ProgramInputs in;
  in.textures["lobe_cube"] = {GL_TEXTURE_CUBE_MAP, tex};
  combiners::apply(p, in);
  EXPECT_EQ(env(GL_TEXTURE1, GL_SRC1_RGB), GL_TEXTURE0);
  EXPECT_EQ(env(GL_TEXTURE1, GL_OPERAND1_RGB), GL_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE0);
  GLint mode = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &mode);
  EXPECT_EQ(mode, GL_NORMAL_MAP);
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_GEN_R));
  EXPECT_TRUE(glIsEnabled(GL_TEXTURE_CUBE_MAP));
  EXPECT_FALSE(glIsEnabled(GL_COLOR_SUM));
  combiners::reset_texture_state(combiners::kMaxStages);
  glDeleteTextures(1, &tex);
}

// The parser takes any texture name; apply() refuses one the path does not provide, naming the
// line of the stage that binds it.
TEST(CombinerState, UnprovidedTextureNamesItsLine) {
  gl::Context ctx(8, 8);
  const combiners::CombinerProgram p = combiners::parse_combiner_program(
      "stage 0\n  texture marble\n  rgb REPLACE texture\n", "marble.comb");
  try {
    combiners::apply(p, {});
    FAIL() << "applied an unprovided texture";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "marble.comb");
    EXPECT_EQ(e.where(), "1");  // the line of the stage that binds it
    EXPECT_NE(e.what_only().find("texture 'marble' is not provided"), std::string::npos);
  }
}

TEST(CombinerState, MissingInputNamesTheStageLine) {
  gl::Context ctx(8, 8);
  try {
    combiners::apply(combiners::load_combiner_program("lobe_vertex.comb"), {});
    FAIL() << "applied without the LUT";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "combiners/lobe_vertex.comb");
    EXPECT_NE(e.what_only().find("power_lut"), std::string::npos) << e.what();
    EXPECT_FALSE(e.where().empty());
  }
}

// ---------------------------------------------------------------------------------------------
// Against the reference

Comparison against_reference(const Scene& scene, const std::string& variant, int w = 0, int h = 0) {
  const Image ref = render_scene(scene, "reference", "", w, h);
  const Image img = render_scene(scene, "combiners", variant, w, h);
  EXPECT_EQ(test::non_finite(img), 0u);
  return compare_images(img, ref, TestEncoding::kUnorm8);
}

// Every variant on every demo scene against the reference: src/paths/bounds/path_bounds.json
// (bounds_test.cpp).

// Hard cases (model.md) through the default variant: finite everywhere (paths_test checks that
// too) and within bounds measured on the per-vertex sampling, set a little above. Cases not
// listed measured 0 LSB (saturated or flat by construction) and get the 1 LSB per-pixel bar.
struct HardBound {
  const char* scene;
  double max_lsb, mean_lsb;
  const char* why;
};

// Measured with this test's own printout (`ltrender_tests --gtest_filter='Hard/CombinersHard*'`)
// on scenes/hard as written by scripts/make_hard_scenes.py. Every sphere case is sphere_s3
// (642 vertices, triangles ~20 pixels across at 160x120): t, attenuation and diffuse are
// interpolated across those triangles, and the LUT texels and every stage output are 8-bit. The
// worst of them measured 4.9 max (thickness_zero_and_one: the thickness-1 sphere carries the
// largest per-vertex terms) and 0.49 mean (distortion_negative), so the shared bound is 6 / 0.6.
constexpr double kPerVertexMaxLsb = 6, kPerVertexMeanLsb = 0.6;
const HardBound kHard[] = {
    // measured 188 / 14.8: the vertex at the light gets att = 1e6 (primary colour clamped to 1)
    // and Gouraud spreads the saturated colour over every triangle around it, where the
    // reference saturates only a few pixels: the documented failure of per-vertex attenuation.
    {"point_light_at_vertex", 255, 16, "per-vertex attenuation at a light touching a vertex"},
};

class CombinersHard : public ::testing::TestWithParam<std::string> {};

TEST_P(CombinersHard, FiniteAndWithinPerVertexBound) {
  const std::string file = GetParam();
  const std::string stem = fs::path(file).stem().string();
  const Scene scene = load_scene(test::source_dir() / "scenes" / "hard" / file);
  const Comparison c = against_reference(scene, "");
  ASSERT_EQ(c.test_non_finite, 0u);
  double max_lsb = kPerVertexMaxLsb, mean_lsb = kPerVertexMeanLsb;
  std::string why = "per-vertex evaluation on sphere_s3 with 8-bit LUT and stages";
  for (const HardBound& b : kHard) {
    if (stem == b.scene) {
      max_lsb = b.max_lsb;
      mean_lsb = b.mean_lsb;
      why = b.why;
    }
  }
  std::printf("%s: max %.2f mean %.3f\n", stem.c_str(), c.covered.max_lsb, c.covered.mean_lsb);
  EXPECT_LE(c.covered.max_lsb, max_lsb) << why;
  EXPECT_LE(c.covered.mean_lsb, mean_lsb) << why;
}

std::vector<std::string> hard_scene_files() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(test::source_dir() / "scenes" / "hard")) {
    if (e.path().extension() == ".json") out.push_back(e.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

INSTANTIATE_TEST_SUITE_P(Hard, CombinersHard, ::testing::ValuesIn(hard_scene_files()),
                         [](const auto& info) {
                           std::string r = fs::path(info.param).stem().string();
                           for (char& ch : r) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return r;
                         });

// A sphere at tessellation s, one directional back light and one point light, p = 8: the
// per-vertex error must fall as the triangles shrink.
Scene sphere_scene(int s, const std::string& projection = "perspective", bool point_light = true) {
  const std::string camera =
      projection == "perspective" ? R"("fov_y_deg": 40)" : R"("height": 2.4)";
  const std::string point =
      R"(, { "type": "point", "position": [1.5, 1, 1.5], "intensity": 2,
             "translucency_scale": 1,
             "attenuation": { "constant": 1, "linear": 0, "quadratic": 0.3 } })";
  const std::string text = R"({
    "image": { "width": 320, "height": 240 },
    "camera": { "eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0],
                "projection": ")" +
                           projection + R"(", )" + camera + R"( },
    "ambient_light": [0.03, 0.03, 0.03],
    "materials": { "m": { "albedo": [0.9, 0.85, 0.8],
                          "translucency": { "power": 8, "distortion": 0.2, "ambient": 0.05,
                                            "thickness": 0.6, "tint": [1, 0.8, 0.6] } } },
    "lights": [ { "type": "directional", "direction": [0.3, 0.1, 1], "intensity": 1.2,
                  "translucency_scale": 2 })" +
                           (point_light ? point : "") + R"( ],
    "objects": [ { "mesh": "sphere_s)" +
                           std::to_string(s) + R"(.ply", "material": "m" } ] })";
  return load_scene(
      parse_scene(text, "sphere_s" + std::to_string(s) + ".json", test::source_dir() / "meshes"));
}

TEST(CombinersTessellation, ErrorFallsAsTheSphereGetsFiner) {
  double previous_mean = 1e9, previous_p99 = 1e9;
  for (int s = 1; s <= 5; ++s) {
    const Comparison c = against_reference(sphere_scene(s), "");
    std::printf("sphere_s%d: max %.2f mean %.3f p99 %.2f\n", s, c.covered.max_lsb,
                c.covered.mean_lsb, c.covered.p99_lsb);
    EXPECT_LT(c.covered.mean_lsb, previous_mean) << "s" << s;
    EXPECT_LE(c.covered.p99_lsb, previous_p99) << "s" << s;
    previous_mean = c.covered.mean_lsb;
    previous_p99 = c.covered.p99_lsb;
  }
  // The finest sphere (81920 faces, ~2 pixels a triangle here) is per-pixel in all but name.
  EXPECT_LE(previous_mean, 0.6);
}

// texgen computes the same affine t per vertex as the CPU does, so the two variants agree to
// float rounding on a scene texgen can serve (orthographic camera, directional lights only).
TEST(CombinersTexgen, MatchesTheCpuVariantWhereApplicable) {
  const Scene scene = sphere_scene(4, "orthographic", false);
  ASSERT_TRUE(texgen_applicable(scene, scene.materials[0]));
  {
    RenderSession session(scene, 16, 16);
    const auto path = session.build(find_path("combiners"), "t=texgen");
    EXPECT_NE(path->stages()[0].name.find("lobe_texgen.comb"), std::string::npos);
  }
  const Image cpu = render_scene(scene, "combiners", "t=vertex");
  const Image gen = render_scene(scene, "combiners", "t=texgen");
  ASSERT_EQ(test::non_finite(gen), 0u);
  const Comparison c = compare_images(gen, cpu, TestEncoding::kUnorm8);
  EXPECT_LE(c.covered.max_lsb, 1.0);
  EXPECT_LE(c.covered.mean_lsb, 0.05);
}

// The issue's bar for lobe=cube: within 2 LSB max of the reference with directional lights and an
// orthographic camera, where the cube holds the exact term per normal and only its 8-bit texels,
// bilinear filtering between texel centres and the output rounding remain (measured max 1.49,
// mean 0.35 on scenes/ortho/backlit_sphere_ortho.json: two lights, two passes).
TEST(CombinersCube, WithinTwoLsbUnderAnOrthographicCamera) {
  const Scene scene =
      load_scene(test::source_dir() / "scenes" / "ortho" / "backlit_sphere_ortho.json");
  const Comparison c = against_reference(scene, "lobe=cube");
  std::printf("cube, ortho: max %.2f mean %.3f\n", c.covered.max_lsb, c.covered.mean_lsb);
  EXPECT_LE(c.covered.max_lsb, 2.0) << "at " << c.covered.max_x << "," << c.covered.max_y;
  EXPECT_LE(c.covered.mean_lsb, 0.5);
}

// Under perspective the cube holds the lobe for the view of the object's centre only; the error
// is reported (bench), here only bounded to catch a broken cube (measured max 122 on
// backlit_sphere: the back-lit lobe is steep in V) and its point lights fall back to per-vertex.
TEST(CombinersCube, PerspectiveIsFiniteAndPointLightsFallBack) {
  const Scene scene = load_scene(test::source_dir() / "scenes" / "coloured_cubes.json");
  RenderSession session(scene, 64, 48);
  const auto path = session.build(find_path("combiners"), "lobe=cube");
  path->frame();
  EXPECT_EQ(test::non_finite(path->result()), 0u);
  const auto stages = path->stages();
  // Two point lights (t=vertex passes) and one directional light (cube pass) per material.
  size_t cube = 0, vertex = 0;
  for (const BuiltStage& s : stages) {
    cube += s.name.find("lobe_cube_full.comb") != std::string::npos;
    vertex += s.name.find("lobe_vertex.comb") != std::string::npos;
  }
  EXPECT_EQ(cube, 2u);
  EXPECT_EQ(vertex, 4u);
  EXPECT_GT(path->frame_stats().cube_rebuild_seconds.value(), 0.0);
}

// Vertex thickness takes the 3-stage program (T from the primary colour, interpolated exactly as
// the reference interpolates it). Its extra error over lobe_cube_full is the 8-bit alpha
// (a + s*lobe)/g times albedo*color*g (~2.2 here, so one alpha step is ~2 LSB): measured max
// 2.33, mean 0.44; bound 3 and 0.5.
TEST(CombinersCube, VertexThicknessProgramUnderOrthographic) {
  Scene scene = sphere_scene(4, "orthographic", false);
  TriangleMesh& mesh = scene.objects[0].mesh;
  mesh.colors.resize(mesh.positions.size());
  for (size_t i = 0; i < mesh.colors.size(); ++i) {
    mesh.colors[i] = glm::dvec3(0.5) + 0.5 * glm::sin(3.0 * mesh.positions[i]);  // smooth, 0..1
  }
  scene.materials[0].translucency->thickness_source = ThicknessSource::Vertex;
  {
    RenderSession session(scene, 16, 16);
    const auto path = session.build(find_path("combiners"), "lobe=cube");
    EXPECT_NE(path->stages()[0].name.find("lobe_cube.comb"), std::string::npos);
  }
  const Comparison c = against_reference(scene, "lobe=cube");
  std::printf("cube, vertex thickness, ortho: max %.2f mean %.3f\n", c.covered.max_lsb,
              c.covered.mean_lsb);
  EXPECT_LE(c.covered.max_lsb, 3.0);
  EXPECT_LE(c.covered.mean_lsb, 0.5);
}

// ---------------------------------------------------------------------------------------------
// Budgets

TEST(CombinerBudget, OneLightTakesTwoStagesInOnePass) {
  const Scene scene = sphere_scene(1, "perspective", false);
  const budget::Report r = combiner_budget(scene, "gl13-2units");
  EXPECT_EQ(r.most("stages"), 2);
  EXPECT_LE(r.most("stages"), 3) << "the issue's bar: one light in <= 3 stages in one pass";
  EXPECT_EQ(r.most("passes"), 1);
  EXPECT_EQ(r.most("texture_units"), 2);
  EXPECT_EQ(r.most("constant_colors"), 1);
  EXPECT_TRUE(r.fits()) << budget::to_text(r);
}

TEST(CombinerBudget, PassesPerLightAndLightLimit) {
  Scene scene = sphere_scene(1);
  EXPECT_EQ(combiner_budget(scene, "gl-8units").most("passes"), 2);
  scene.lights.resize(9, scene.lights[0]);
  const budget::Report r = combiner_budget(scene, "gl-8units");
  EXPECT_EQ(r.most("passes"), 9);
  EXPECT_FALSE(r.fits());
  ASSERT_EQ(r.items.size(), 1u) << "one material";
  EXPECT_NE(r.first_overrun().find("lights: 9 > 8 (gl-8units)"), std::string::npos)
      << r.first_overrun();
  const auto j = nlohmann::json::parse(budget::to_json(r));
  EXPECT_EQ(j["fits"], false);
  ASSERT_EQ(j["over"].size(), 1u) << j.dump();
  EXPECT_EQ(j["over"][0]["key"], "lights");
  EXPECT_EQ(j["over"][0]["used"], 9);
  EXPECT_EQ(j["over"][0]["limit"], 8);
}

TEST(CombinerBudget, UnknownProfileIsAnInputError) {
  const Scene scene = sphere_scene(1);
  try {
    combiner_budget(scene, "gl12");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--profile");
    EXPECT_NE(e.what_only().find("gl13-2units"), std::string::npos);
  }
}

// The Wii's profile moved to the gx path, which counts a real TEV: asking the GL path for it
// says where it went.
TEST(CombinerBudget, WiiProfileBelongsToTheGxPath) {
  const Scene scene = sphere_scene(1);
  try {
    combiner_budget(scene, "wii-tev");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("--path gx"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace lt
