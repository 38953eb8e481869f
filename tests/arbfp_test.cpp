// The arbfp path: variant names, the generator (only what the scene uses), every variant against
// the reference on every demo scene with its own documented threshold, and no NaN/Inf from any
// variant on the hard scenes (the default variant also runs in paths_test's HardScene).
#include <gtest/gtest.h>

#include <cmath>

#include "arb/arb_ir_counter.h"
#include "arb/arb_program.h"
#include "arb_ir_query.h"
#include "arb_test_util.h"
#include "gl/program.h"
#include "metrics/compare.h"
#include "model/pow_curves.h"
#include "model/translucency.h"
#include "paths/arbfp/arb_generator.h"
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

// A tiny scene for the generator tests (no meshes needed: generation is CPU only).
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

bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

using arbfp::ir::Op;
using test::count_op;
using test::has_op;

// Each feature's instructions only when the scene uses it; counted on the instruction list.
TEST(ArbfpGenerator, EmitsOnlyWhatTheSceneUses) {
  const arbfp::PowVariant exact;
  {
    const Scene s = small_scene(false, false);
    const auto p = arbfp::generate_arb(s, s.materials[0], exact);
    const auto& fp = p.fragment_program;
    EXPECT_FALSE(has_op(fp, Op::RCP)) << "attenuation only for point lights";
    EXPECT_FALSE(test::declares_param(fp, "ambient_light")) << "ambient only when non-zero";
    EXPECT_EQ(count_op(fp, Op::RSQ), 2) << "N and V: normalised H only on request";
    EXPECT_FALSE(test::reads_attrib(p.vertex_program, "vertex.color"))
        << "constant thickness needs no vertex colour";
    EXPECT_FALSE(test::reads_attrib(fp, "fragment.texcoord[2]"));
    EXPECT_EQ(count_op(fp, Op::POW), 1);
    EXPECT_FALSE(p.lut.has_value());
  }
  {
    Scene s = small_scene(true, true);
    s.materials[0].translucency->normalize_distorted_light = true;
    s.materials[0].translucency->thickness_source = ThicknessSource::Vertex;
    const auto p = arbfp::generate_arb(s, s.materials[0], exact);
    const auto& fp = p.fragment_program;
    EXPECT_EQ(count_op(fp, Op::RCP), 2) << "dist = 1 / RSQ(dist^2), then the attenuation";
    EXPECT_TRUE(test::declares_param(fp, "ambient_light"));
    EXPECT_EQ(count_op(fp, Op::RSQ), 4) << "N, V, the point light's L and H";
    // The tint is applied per vertex, so the fragment program reads T straight from texcoord[2].
    EXPECT_TRUE(test::writes_output(p.vertex_program, "result.texcoord[2]"));
    EXPECT_TRUE(test::reads_attrib(p.vertex_program, "vertex.color"));
    EXPECT_TRUE(test::reads_attrib(fp, "fragment.texcoord[2]"));
    EXPECT_FALSE(test::declares_param(fp, "tint"));
  }
  {
    // Without the term: no view vector, no lobe.
    const Scene s = small_scene(false, false);
    const auto p = arbfp::generate_arb(s, s.materials[0], exact, false);
    EXPECT_FALSE(has_op(p.fragment_program, Op::POW));
    EXPECT_EQ(count_op(p.fragment_program, Op::RSQ), 1) << "N only";
  }
}

TEST(ArbfpGenerator, PowerZeroHasNoPowAtAll) {
  Scene s = small_scene(false, false);
  s.materials[0].translucency->power = 0;
  for (const std::string& n : variant_names()) {
    const auto& fp =
        arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant(n)).fragment_program;
    EXPECT_FALSE(has_op(fp, Op::POW) || has_op(fp, Op::TEX) || has_op(fp, Op::EX2)) << n;
  }
}

TEST(ArbfpGenerator, MulFallsBackToExactForNonIntegerPowerAndSaysSo) {
  Scene s = small_scene(false, false);
  s.materials[0].translucency->power = 2.5;
  const auto p = arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant("pow=mul"));
  EXPECT_EQ(count_op(p.fragment_program, Op::POW), 1);
  ASSERT_FALSE(p.notes.empty());
  EXPECT_TRUE(contains(p.notes.front(), "not an integer"));
  s.materials[0].translucency->power = 8;
  const auto q = arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant("pow=mul"));
  EXPECT_FALSE(has_op(q.fragment_program, Op::POW)) << "no POW for pow=mul with integer p";
  EXPECT_EQ(test::count_squarings(q.fragment_program), 3) << "t^8 by three squarings";
}

// The LUT replaces POW by one TEX per light, and its coordinate remaps all come before the first
// TEX, so any light count stays at 2 texture indirections (ARB_fragment_program issue 24).
TEST(ArbfpGenerator, LutIsOneTexPerLightInTwoIndirections) {
  const arbfp::PowVariant lut = arbfp::parse_variant("pow=lut:256:u8");
  for (size_t lights : {1u, 2u, 5u, 9u}) {
    Scene s = small_scene(false, false);
    while (s.lights.size() < lights) s.lights.push_back(s.lights.front());
    const auto p = arbfp::generate_arb(s, s.materials[0], lut);
    const budget::ProgramCounts c = arbfp::ir::count(p.fragment_program);
    EXPECT_EQ(c.tex, static_cast<int>(lights)) << lights << " lights";
    EXPECT_EQ(c.indirections, 2) << lights << " lights";
    EXPECT_FALSE(has_op(p.fragment_program, Op::POW)) << lights << " lights";
    ASSERT_TRUE(p.lut.has_value());
    EXPECT_EQ(p.lut->size, 256);
  }
  // Without a texture there is one indirection.
  const Scene s = small_scene(false, false);
  const auto sg = arbfp::generate_arb(s, s.materials[0], arbfp::parse_variant("pow=sg"));
  EXPECT_EQ(arbfp::ir::count(sg.fragment_program).indirections, 1);
  EXPECT_EQ(count_op(sg.fragment_program, Op::EX2), 1);
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
      const auto& vp = p.vertex_program;
      const auto& fp = p.fragment_program;
      const std::string what =
          std::string(point ? "point" : "directional") + " p " + std::to_string(power);
      // The term in the vertex program: t = dot(V, -H) saturated by MAX/MIN (no _SAT in
      // ARB_vertex_program; the IR refuses it and CMP there), the lobe, and its hand-over to the
      // fragment program.
      EXPECT_EQ(count_op(vp, Op::MAX), power == 4 ? 1 : 2) << what << ": saturate (and POW floor)";
      EXPECT_EQ(count_op(vp, Op::MIN), point ? 5 : 3) << what << ": 1/|n|, 1/|V|, (L, H,) t <= 1";
      EXPECT_TRUE(test::writes_output(vp, "result.texcoord[3]", "x")) << what;
      EXPECT_FALSE(test::saturates(vp) || has_op(vp, Op::CMP)) << what << ": not in ARBvp1.0";
      if (power == 4) {
        EXPECT_EQ(test::count_squarings(vp), 2) << what << ": t^4 by two squarings";
        EXPECT_FALSE(has_op(vp, Op::POW)) << what;
      } else {
        // Non-integer p: POW per vertex of t floored at 2^-126, masked by (t > 0) for 0^p = 0.
        EXPECT_EQ(count_op(vp, Op::POW), 1) << what;
        EXPECT_EQ(count_op(vp, Op::SLT), 1) << what;
        ASSERT_FALSE(p.notes.empty());
        EXPECT_TRUE(contains(p.notes.front(), "not an integer")) << what;
      }
      if (point) {
        // L = N at distance 0, selected by a mask (no CMP in vertex programs); normalised H.
        EXPECT_EQ(count_op(vp, Op::SGE), 2) << what << ": the zero normal and distance 0";
        EXPECT_EQ(count_op(vp, Op::RSQ), 4) << what << ": N, V, L and H";
        // Diffuse and attenuation stay per pixel.
        EXPECT_EQ(count_op(fp, Op::RCP), 2) << what;
      }
      // The fragment program: no t, no V, no H, no lobe math; only lobe * T + diffuse per light
      // on top of the program without the term.
      for (Op gone : {Op::POW, Op::EX2, Op::LG2, Op::TEX}) {
        EXPECT_FALSE(has_op(fp, gone)) << what << ": " << arbfp::ir::info(gone).name;
      }
      EXPECT_EQ(count_op(fp, Op::RSQ), point ? 2 : 1) << what << ": N (and L), no V or H";
      const auto base = arbfp::generate_arb(s, s.materials[0], pv, false);
      EXPECT_EQ(arbfp::ir::count(fp).alu, arbfp::ir::count(base.fragment_program).alu + 1) << what;
      EXPECT_TRUE(test::reads_attrib(fp, "fragment.texcoord[3]", "x")) << what;
    }
  }
  // Without the term (the budget's baseline) the vertex program has no lobe either.
  const Scene s = small_scene(false, false);
  const auto p = arbfp::generate_arb(s, s.materials[0], pv, false);
  EXPECT_FALSE(test::writes_output(p.vertex_program, "result.texcoord[3]", "x"));
  EXPECT_FALSE(test::reads_attrib(p.fragment_program, "fragment.texcoord[3]"));
  EXPECT_EQ(p.vertex_program.instructions().size(), 2u) << "position and normal only";
}

// Lights 0-3 in texcoord[3], 4-7 in texcoord[4] ...; ps_2_0's 8 texcoords end at 20 lights.
TEST(ArbfpGenerator, PerVertexLobePacksFourLightsPerTexcoord) {
  const arbfp::PowVariant pv = arbfp::parse_variant("pow=mul:vertex");
  Scene s = small_scene(false, false);
  while (s.lights.size() < 6) s.lights.push_back(s.lights.front());
  const auto p = arbfp::generate_arb(s, s.materials[0], pv);
  EXPECT_TRUE(test::writes_output(p.vertex_program, "result.texcoord[3]", "xyzw"));
  EXPECT_TRUE(test::writes_output(p.vertex_program, "result.texcoord[4]", "xy"));
  EXPECT_TRUE(test::reads_attrib(p.fragment_program, "fragment.texcoord[4]", "y"));
  EXPECT_FALSE(test::reads_attrib(p.fragment_program, "fragment.texcoord[4]", "z"));
  while (s.lights.size() < arbfp::kMaxVertexLobeLights + 1) s.lights.push_back(s.lights.front());
  EXPECT_THROW(arbfp::generate_arb(s, s.materials[0], pv), InputError);
}

struct VariantCase {
  std::string scene, variant;
};

void PrintTo(const VariantCase& c, std::ostream* os) {
  *os << c.scene << " " << c.variant;
}

// Every variant on every demo scene against the reference: src/paths/bounds/path_bounds.json
// (bounds_test.cpp).

// Every variant on every hard scene: finite everywhere (POW of 0 through LG2/EX2 is NaN unless
// guarded, RSQ(0) is inf, a light at distance 0 divides by 0). The 8-bit framebuffer would hide a
// NaN (it stores 0), so the programs draw into an RGBA32F target here, where NaN and Inf stay
// visible (float colour buffers are not clamped), and every value is checked.
std::vector<VariantCase> arbfp_hard_cases() {
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
  const std::vector<float> px = test::frame_in_float_target(*path, scene.width, scene.height);
  size_t bad = 0, lit = 0;
  for (size_t i = 0; i < px.size(); i += 4) {
    for (size_t k = 0; k < 3; ++k) bad += !std::isfinite(px[i + k]);
    lit += px[i + 3] > 0.5f;
  }
  EXPECT_EQ(bad, 0u) << "non-finite values in the float target";
  EXPECT_GT(lit, 0u) << "nothing drawn";
}

INSTANTIATE_TEST_SUITE_P(Hard, ArbfpHard, ::testing::ValuesIn(arbfp_hard_cases()),
                         [](const auto& info) {
                           return test::test_param_name(fs::path(info.param.scene).stem().string() +
                                                        "__" + info.param.variant);
                         });

}  // namespace
}  // namespace lt
