// The arbfp path: variant names, the generator (only what the scene uses), every variant against
// the reference on every demo scene with its own documented threshold, and no NaN/Inf from any
// variant on the hard scenes (the default variant also runs in paths_test's HardScene).
#include <gtest/gtest.h>

#include <cmath>

#include "arb_test_util.h"
#include "gl/program.h"
#include "metrics/compare.h"
#include "model/pow_curves.h"
#include "model/translucency.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_program.h"
#include "paths/arbfp/arbfp_path.h"
#include "render/session.h"

namespace lt {
namespace {

using arbfp::PowMethod;

std::vector<std::string> variant_names() {
  std::vector<std::string> out;
  for (const VariantInfo& v : arbfp_path_info().variants) out.push_back(v.name);
  return out;
}

TEST(ArbfpVariants, EveryListedNameParsesAndRoundTrips) {
  for (const std::string& n : variant_names()) EXPECT_EQ(arbfp::parse_variant(n).name(), n);
  const arbfp::PowVariant v = arbfp::parse_variant("pow=lut:128:f16");
  EXPECT_EQ(v.method, PowMethod::Lut);
  EXPECT_EQ(v.lut_size, 128);
  EXPECT_EQ(v.lut_format, model::LutFormat::F16);
}

TEST(ArbfpVariants, MalformedNamesAreInputErrors) {
  for (const char* bad :
       {"exact", "pow=", "pow=lut", "pow=lut:1:u8", "pow=lut:64:u16", "pow=lut:64:u8x",
        "pow=lut:064:u8", "pow=cubic", "pow=mul:", "pow=exact:vertex", "pow=mul:vertexx"}) {
    EXPECT_THROW(arbfp::parse_variant(bad), InputError) << bad;
  }
}

TEST(ArbfpVariants, FittedExponentBeatsTheSeedsOnTheLobe) {
  for (double p : {2.0, 4.0, 8.0, 32.0}) {
    auto max_error = [p](double n) {
      double e = 0;
      for (int i = 0; i <= 2000; ++i) {
        const double t = i / 2000.0;
        e = std::max(e, std::abs(model::sg_curve(t, n) - std::pow(t, p)));
      }
      return e;
    };
    const double fitted = model::fit_sg_exponent(p);
    EXPECT_LT(max_error(fitted), max_error(model::sg_exponent(p))) << p;
    EXPECT_NEAR(model::sg_exponent(p), 1.4427 * p + 1.4427, 1e-3 * (p + 1));
  }
}

// A tiny scene for the generator tests (no meshes needed: generation is text only).
Scene small_scene(bool point, bool ambient) {
  Scene s;
  Material m;
  m.name = "m";
  m.translucency = Translucency{};
  m.translucency->power = 4;
  s.materials.push_back(m);
  Light l;
  if (point) {
    l.type = Light::Type::Point;
    l.position = {1, 2, 3};
  }
  s.lights.push_back(l);
  if (ambient) s.ambient_light = {0.1, 0.1, 0.1};
  return s;
}

// Whether a program's code (comments stripped: the templates mention every feature) has `what`.
bool has(const std::string& text, const std::string& what) {
  std::string code;
  size_t pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(pos, end - pos);
    code += line.substr(0, line.find('#')) + "\n";
    pos = end + 1;
  }
  return code.find(what) != std::string::npos;
}

TEST(ArbfpGenerator, EmitsOnlyWhatTheSceneUses) {
  const arbfp::PowVariant exact;
  {
    const Scene s = small_scene(false, false);
    const auto p = arbfp::generate_arb(s, s.materials[0], exact);
    EXPECT_FALSE(has(p.fragment, "att0")) << "attenuation only for point lights";
    EXPECT_FALSE(has(p.fragment, "ambient_light")) << "ambient only when non-zero";
    EXPECT_FALSE(has(p.fragment, "RSQ H.w")) << "normalised H only on request";
    EXPECT_FALSE(has(p.vertex, "texcoord[2]")) << "constant thickness needs no vertex colour";
    EXPECT_TRUE(has(p.fragment, "POW"));
    EXPECT_FALSE(p.lut.has_value());
  }
  {
    Scene s = small_scene(true, true);
    s.materials[0].translucency->normalize_distorted_light = true;
    s.materials[0].translucency->thickness_source = ThicknessSource::Vertex;
    const auto p = arbfp::generate_arb(s, s.materials[0], exact);
    EXPECT_TRUE(has(p.fragment, "RCP att0.x"));
    EXPECT_TRUE(has(p.fragment, "ambient_light"));
    EXPECT_TRUE(has(p.fragment, "RSQ H.w"));
    // The tint is applied per vertex, so the fragment program reads T straight from texcoord[2].
    EXPECT_TRUE(has(p.vertex, "MUL result.texcoord[2], vertex.color, tint"));
    EXPECT_FALSE(has(p.fragment, "tint"));
  }
  {
    // Without the term: no view vector, no lobe.
    const Scene s = small_scene(false, false);
    const auto p = arbfp::generate_arb(s, s.materials[0], exact, false);
    EXPECT_FALSE(has(p.fragment, "POW"));
    EXPECT_FALSE(has(p.fragment, "MUL V.xyz"));
  }
}

TEST(ArbfpGenerator, PowerZeroHasNoPowAtAll) {
  Scene s = small_scene(false, false);
  s.materials[0].translucency->power = 0;
  for (const std::string& n : variant_names()) {
    const auto p = arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant(n));
    EXPECT_FALSE(has(p.fragment, "POW") || has(p.fragment, "TEX") || has(p.fragment, "EX2")) << n;
  }
}

TEST(ArbfpGenerator, MulFallsBackToExactForNonIntegerPowerAndSaysSo) {
  Scene s = small_scene(false, false);
  s.materials[0].translucency->power = 2.5;
  const auto p = arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant("pow=mul"));
  EXPECT_TRUE(has(p.fragment, "POW"));
  ASSERT_FALSE(p.notes.empty());
  EXPECT_TRUE(has(p.notes.front(), "not an integer"));
  s.materials[0].translucency->power = 8;
  const auto q = arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant("pow=mul"));
  EXPECT_FALSE(has(q.fragment, "POW"));
}

// pow=mul:vertex: the lobe is the vertex program's; the fragment program only reads it.
TEST(ArbfpGenerator, PerVertexLobeIsInTheVertexProgramOnly) {
  const arbfp::PowVariant pv = arbfp::parse_variant("pow=mul:vertex");
  EXPECT_TRUE(pv.per_vertex);
  EXPECT_EQ(pv.method, PowMethod::Mul);
  for (bool point : {false, true}) {
    for (double power : {4.0, 2.5}) {
      Scene s = small_scene(point, false);
      s.materials[0].translucency->power = power;
      s.materials[0].translucency->normalize_distorted_light = point;
      const auto p = arbfp::generate_arb(s, s.materials[0], pv);
      const std::string what =
          std::string(point ? "point" : "directional") + " p " + std::to_string(power);
      // The term in the vertex program: H = L + N*d, t = dot(V, -H) saturated by MAX/MIN (no
      // _SAT in ARB_vertex_program), the lobe, and its hand-over to the fragment program.
      EXPECT_TRUE(has(p.vertex, "MAD H.xyz, N, material.x")) << what;
      EXPECT_TRUE(has(p.vertex, "DP3 tv0.x, V, -H")) << what;
      EXPECT_TRUE(has(p.vertex, "MAX tv0.x, tv0, material.w")) << what;
      EXPECT_TRUE(has(p.vertex, "MIN tv0.x, tv0, guard.z")) << what;
      EXPECT_TRUE(has(p.vertex, "result.texcoord[3].x, lobe0")) << what;
      EXPECT_FALSE(has(p.vertex, "_SAT") || has(p.vertex, "CMP")) << what << ": not in ARBvp1.0";
      if (power == 4) {
        EXPECT_TRUE(has(p.vertex, "MUL lobe0.x, tv0, tv0")) << what;
        EXPECT_FALSE(has(p.vertex, "POW")) << what;
      } else {
        // Non-integer p: POW per vertex of t floored at 2^-126, masked by (t > 0) for 0^p = 0.
        EXPECT_TRUE(has(p.vertex, "POW lobe0.x, r.x, material.y")) << what;
        EXPECT_TRUE(has(p.vertex, "SLT r.x, material.w, tv0")) << what;
        ASSERT_FALSE(p.notes.empty());
        EXPECT_TRUE(has(p.notes.front(), "not an integer")) << what;
      }
      if (point) {
        // L = N at distance 0, selected by a mask (no CMP in vertex programs).
        EXPECT_TRUE(has(p.vertex, "SGE r.y, -L.w, material.w")) << what;
        EXPECT_TRUE(has(p.vertex, "RSQ H.w")) << what;
        // Diffuse and attenuation stay per pixel.
        EXPECT_TRUE(has(p.fragment, "RCP att0.x")) << what;
      }
      // The fragment program: no t, no V, no H, no lobe math; only lobe * T + diffuse.
      for (const char* gone :
           {"POW", "EX2", "LG2", "TEX", "tv0", "lobe0", "H.xyz", "V.xyz", "material"}) {
        EXPECT_FALSE(has(p.fragment, gone)) << what << ": " << gone;
      }
      EXPECT_TRUE(has(p.fragment, "MAD acc.xyz, fragment.texcoord[3].x, T, diffuse0.x")) << what;
    }
  }
  // Without the term (the budget's baseline) the vertex program has no lobe either.
  const Scene s = small_scene(false, false);
  const auto p = arbfp::generate_arb(s, s.materials[0], pv, false);
  EXPECT_FALSE(has(p.vertex, "texcoord[3]"));
  EXPECT_FALSE(has(p.fragment, "texcoord[3]"));
}

// Lights 0-3 in texcoord[3], 4-7 in texcoord[4] ...; ps_2_0's 8 texcoords end at 20 lights.
TEST(ArbfpGenerator, PerVertexLobePacksFourLightsPerTexcoord) {
  const arbfp::PowVariant pv = arbfp::parse_variant("pow=mul:vertex");
  Scene s = small_scene(false, false);
  while (s.lights.size() < 6) s.lights.push_back(s.lights.front());
  const auto p = arbfp::generate_arb(s, s.materials[0], pv);
  EXPECT_TRUE(has(p.vertex, "result.texcoord[3].xyzw, lobe0"));
  EXPECT_TRUE(has(p.vertex, "result.texcoord[4].xy, lobe1"));
  EXPECT_TRUE(has(p.fragment, "fragment.texcoord[4].y"));
  while (s.lights.size() < arbfp::kMaxVertexLobeLights + 1) s.lights.push_back(s.lights.front());
  EXPECT_THROW(arbfp::generate_arb(s, s.materials[0], pv), InputError);
}

struct VariantCase {
  std::string scene, variant;
};

void PrintTo(const VariantCase& c, std::ostream* os) {
  *os << c.scene << " " << c.variant;
}

// Every variant on every demo scene against the reference: tests/bounds.json (bounds_test.cpp).

// Every variant on every hard scene: finite everywhere (POW of 0 through LG2/EX2 is NaN unless
// guarded, RSQ(0) is inf, a light at distance 0 divides by 0). The 8-bit framebuffer would hide a
// NaN (it stores 0), so the programs draw into an RGBA32F target here, where NaN and Inf stay
// visible (float colour buffers are not clamped), and every value is checked.
std::vector<VariantCase> hard_cases() {
  std::vector<VariantCase> out;
  for (const std::string& s : test::json_files("scenes/hard")) {
    for (const std::string& v : variant_names()) out.push_back({s, v});
  }
  return out;
}

class ArbfpHard : public ::testing::TestWithParam<VariantCase> {};

// The method itself: Inf and NaN written by a fragment program do reach the float target. (On
// Mesa, ARB programs multiply with D3D9 rules, 0 * inf = 0, so an unguarded 0 * RSQ(0) happens to
// stay finite there; the guards stay, because the ARB spec leaves it IEEE on other hardware.)
TEST(ArbfpHardMethod, FloatTargetShowsAnUnguardedNan) {
  gl::Context ctx(4, 4);
  gl::FloatTarget target(4, 4, 1);
  target.bind();
  const arbfp::ArbProgram fp(GL_FRAGMENT_PROGRAM_ARB,
                             "!!ARBfp1.0\nPARAM z = {0, 0, 0, 0};\nPARAM one = {1, 1, 1, 1};\n"
                             "TEMP a;\nRSQ a.x, z.x;\nMOV result.color.x, a.x;\n"
                             "SUB result.color.y, a.x, a.x;\nMOV result.color.z, z.x;\n"
                             "MOV result.color.w, one.x;\nEND",
                             "nan");
  glViewport(0, 0, 4, 4);
  glEnable(GL_FRAGMENT_PROGRAM_ARB);
  fp.bind();
  glBegin(GL_QUADS);
  glVertex2f(-1, -1);
  glVertex2f(1, -1);
  glVertex2f(1, 1);
  glVertex2f(-1, 1);
  glEnd();
  glDisable(GL_FRAGMENT_PROGRAM_ARB);
  glFinish();
  std::vector<float> px;
  target.read(0, px);
  target.unbind();
  ASSERT_EQ(px.size(), 4u * 4 * 4);
  EXPECT_TRUE(std::isinf(px[0])) << px[0];  // RSQ(0) = +inf
  EXPECT_TRUE(std::isnan(px[1])) << px[1];  // inf - inf
  EXPECT_EQ(px[2], 0.0f);
}

TEST_P(ArbfpHard, NoNanOrInfEvenInAFloatTarget) {
  const VariantCase& c = GetParam();
  const Scene scene = test::load_test_scene(c.scene);
  RenderSession session(scene, scene.width, scene.height);
  auto path = session.build(find_path("arbfp"), c.variant);
  gl::FloatTarget target(scene.width, scene.height, 1);
  target.bind();
  path->frame();
  glFinish();
  std::vector<float> px;
  target.read(0, px);
  target.unbind();
  size_t bad = 0, lit = 0;
  for (size_t i = 0; i < px.size(); i += 4) {
    for (size_t k = 0; k < 3; ++k) bad += !std::isfinite(px[i + k]);
    lit += px[i + 3] > 0.5f;
  }
  EXPECT_EQ(bad, 0u) << "non-finite values in the float target";
  EXPECT_GT(lit, 0u) << "nothing drawn";
}

INSTANTIATE_TEST_SUITE_P(Hard, ArbfpHard, ::testing::ValuesIn(hard_cases()), [](const auto& info) {
  return test::test_param_name(fs::path(info.param.scene).stem().string() + "__" +
                               info.param.variant);
});

}  // namespace
}  // namespace lt
