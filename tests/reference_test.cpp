// Analytic checks of the reference path (pbrt's way: known answers, not goldens). A flat quad
// facing an orthographic camera under a directional light has one colour everywhere, computed
// here by hand from model.md for several parameter sets.
#include <gtest/gtest.h>

#include <cmath>

#include "load/load_scene.h"
#include "model/translucency.h"
#include "render/session.h"
#include "scene/scene_parse.h"
#include "test_util.h"

namespace lt {
namespace {

struct QuadCase {
  const char* name;
  double power, distortion, ambient, scale;
  glm::dvec3 light_dir;  // direction the light travels
  glm::dvec3 albedo, color, thickness, ambient_light;
  bool normalize_h;
  glm::dvec3 expected;  // worked out by hand in the comment of each case
};

void PrintTo(const QuadCase& c, std::ostream* os) {
  *os << c.name;
}

std::string quad_scene(const QuadCase& c) {
  auto v3 = [](const glm::dvec3& v) {
    char b[128];
    std::snprintf(b, sizeof b, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
    return std::string(b);
  };
  char buf[2048];
  std::snprintf(buf, sizeof buf, R"({
    "image": {"width": 32, "height": 32},
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "projection": "orthographic", "height": 1,
               "near": 1, "far": 10},
    "ambient_light": %s,
    "materials": {"m": {"albedo": %s, "translucency": {"power": %.17g, "distortion": %.17g,
      "ambient": %.17g, "thickness": %s, "normalize_distorted_light": %s}}},
    "lights": [{"type": "directional", "direction": %s, "color": %s,
                "translucency_scale": %.17g}],
    "objects": [{"mesh": "quad.obj", "material": "m"}]
  })",
                v3(c.ambient_light).c_str(), v3(c.albedo).c_str(), c.power, c.distortion, c.ambient,
                v3(c.thickness).c_str(), c.normalize_h ? "true" : "false", v3(c.light_dir).c_str(),
                v3(c.color).c_str(), c.scale);
  return buf;
}

// The quad's normal is +Z and the orthographic view vector V is +Z everywhere.
const QuadCase kQuadCases[] = {
    // Backlit: L = (0,0,-1), diffuse 0; H = L + N*0.2 = (0,0,-0.8); t = 0.8; 0.8^4 = 0.4096.
    // trans = (0.4096*2 + 0.1) * T(0.5) = 0.9192 * 0.5 = 0.4596; c = albedo 0.9 * 0.4596 = 0.41364.
    {"backlit_p4",
     4,
     0.2,
     0.1,
     2,
     {0, 0, 1},
     glm::dvec3(0.9),
     glm::dvec3(1),
     glm::dvec3(0.5),
     glm::dvec3(0),
     false,
     glm::dvec3(0.41364)},
    // 0^0: front light L = (0,0,1): diffuse 1; H = (0,0,1), t = sat(-1) = 0; p = 0 so lobe = 1.
    // c = 0.5 * (1 + (1*1 + 0)*1) = 1.0.
    {"zero_pow_zero",
     0,
     0,
     0,
     1,
     {0, 0, -1},
     glm::dvec3(0.5),
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(0),
     false,
     glm::dvec3(1.0)},
    // Huge p: backlit, d = 0.5: t = 0.5, 0.5^1024 underflows to ~5.6e-309 in double: 0 in any
    // 8-bit or float image. c = 1 * (0.05 + (0 * 3 + 0.25) * 0.8) = 0.25.
    {"huge_power_1024",
     1024,
     0.5,
     0.25,
     3,
     {0, 0, 1},
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(0.8),
     glm::dvec3(0.05),
     false,
     glm::dvec3(0.25)},
    // Fractional p, coloured: backlit, d = 0: t = 1, lobe = 1 for any p.
    // c = albedo * color * (1*0.5 + 0) * T = (0.8*1*0.5*1, 0.6*0.5*0.5*0.5, 0.4*0.25*0.5*0.2).
    {"coloured_fractional",
     2.5,
     0,
     0,
     0.5,
     {0, 0, 1},
     {0.8, 0.6, 0.4},
     {1, 0.5, 0.25},
     {1, 0.5, 0.2},
     glm::dvec3(0),
     false,
     {0.4, 0.075, 0.01}},
    // Grazing light from the side, 60 degrees behind: direction = (sin60, 0, cos60) so
    // L = (-0.8660254, 0, -0.5); diffuse 0. d = 1: H = (-0.8660254, 0, 0.5), t = sat(-0.5) = 0.
    // p = 3: lobe 0. c = 1 * (0 + (0 + 0.2) * 1) = 0.2 (the ambient translucency alone).
    {"negative_dot",
     3,
     1,
     0.2,
     4,
     {0.8660254037844386, 0, 0.5},
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(0),
     false,
     glm::dvec3(0.2)},
    // Normalised H: same light, d = -1 (negative distortion, |H| > 1):
    // H = L - N = (-0.8660254, 0, -1.5), |H| = sqrt(0.75 + 2.25) = sqrt(3); H/|H| z = -0.8660254;
    // t = 0.8660254, p = 2: 0.75. c = 1 * ((0.75 * 1 + 0) * 1) = 0.75.
    {"normalized_h",
     2,
     -1,
     0,
     1,
     {0.8660254037844386, 0, 0.5},
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(0),
     true,
     glm::dvec3(0.75)},
    // Saturating scale: backlit, d = 0, t = 1: c = 1 * (1 * 50) * 1 = 50 (HDR, unclamped in EXR).
    {"saturating_scale",
     8,
     0,
     0,
     50,
     {0, 0, 1},
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(1),
     glm::dvec3(0),
     false,
     glm::dvec3(50)},
    // Thickness 0: only diffuse remains; front light at 60 deg: diffuse = cos60 = 0.5.
    // c = 0.6 * (0.5 + anything * 0) = 0.3.
    {"thickness_zero",
     4,
     0.2,
     0.3,
     2,
     {-0.8660254037844386, 0, -0.5},
     glm::dvec3(0.6),
     glm::dvec3(1),
     glm::dvec3(0),
     glm::dvec3(0),
     false,
     glm::dvec3(0.3)},
};

class ReferenceQuad : public ::testing::TestWithParam<QuadCase> {};

TEST_P(ReferenceQuad, EveryCoveredPixelHasTheHandComputedColour) {
  const QuadCase& c = GetParam();
  test::TempDir dir;
  test::write_file(dir / "quad.obj", test::quad_obj());
  const Scene scene = load_scene(parse_scene(quad_scene(c), dir / "quad.json", dir.path()));
  const Image img = render_scene(scene, "reference", "");
  // The quad (side 2) fills the orthographic view (height 1): every pixel is covered.
  size_t covered = 0;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      ASSERT_EQ(p[3], 1.0f) << "pixel " << x << "," << y << " not covered";
      for (int ch = 0; ch < 3; ++ch) {
        // The G-buffer is float: inputs carry ~1e-7 relative error before the double shading.
        ASSERT_NEAR(p[ch], c.expected[ch], 1e-5 * std::max(1.0, c.expected[ch]))
            << c.name << " pixel " << x << "," << y << " channel " << ch;
      }
      ++covered;
    }
  }
  EXPECT_EQ(covered, 32u * 32u);
}

INSTANTIATE_TEST_SUITE_P(Analytic, ReferenceQuad, ::testing::ValuesIn(kQuadCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Model, LobeConventions) {
  EXPECT_EQ(model::lobe(0.0, 0.0), 1.0);  // 0^0 := 1
  EXPECT_EQ(model::lobe(0.0, 8.0), 0.0);
  EXPECT_EQ(model::lobe(0.5, 1024.0), std::pow(0.5, 1024.0));
  EXPECT_DOUBLE_EQ(model::lobe(0.25, 0.5), 0.5);
}

TEST(Model, PointLightAtTheShadedPointIsFiniteAndHeadOn) {
  Light l;
  l.type = Light::Type::Point;
  l.position = {1, 2, 3};
  l.kc = 0;
  l.kl = 0;
  l.kq = 1;
  const model::LightSample s = model::sample_light(l, {1, 2, 3}, {0, 1, 0});
  EXPECT_EQ(s.L, glm::dvec3(0, 1, 0));
  EXPECT_TRUE(std::isfinite(s.attenuation));
  EXPECT_EQ(s.attenuation, 1.0 / model::kMinAttenuationDenominator);
}

TEST(Model, ZeroNormalShadesAsNoNormal) {
  Scene scene;
  Light l;
  l.direction = {0, 0, 1};
  scene.lights = {l};
  Material m;
  Translucency tr;
  tr.power = 2;
  tr.distortion = 5;  // must play no part without a normal
  m.translucency = tr;
  model::SurfacePoint sp;
  sp.P = {0, 0, 0};
  sp.N = {0, 0, 0};
  sp.V = {0, 0, 1};
  // No normal: diffuse 0, H = L = (0,0,-1), t = 1, lobe 1: c = 1 * (1 * 1 + 0) * 1 = 1.
  const glm::dvec3 c = model::shade(scene, m, sp);
  EXPECT_DOUBLE_EQ(c.r, 1.0);
}

}  // namespace
}  // namespace lt
