// The half path: the seed's fp16 arithmetic emulated on the CPU. Analytic flat-quad cases with
// the expected value worked out step by step in binary16 (each step rounded to nearest even),
// every demo scene against the reference with measured bars, and the hard cases' fp16 intent
// (guarded variants finite; the unguarded variant counts its NaN/Inf pixels and marks them).
#include <gtest/gtest.h>

#include <cmath>

#include "load/load_scene.h"
#include "metrics/compare.h"
#include "render/session.h"
#include "scene/scene_parse.h"
#include "test_util.h"

namespace lt {
namespace {

struct Rendered {
  Image image;
  FrameStats stats;
};

// render_scene, keeping the path's frame_stats (nonfinite_pixels).
Rendered render_half(const Scene& scene, const std::string& variant, int width = 0,
                     int height = 0) {
  RenderSession session(scene, width > 0 ? width : scene.width, height > 0 ? height : scene.height);
  const PathInfo& info = find_path("half");
  auto path = session.build(info, resolve_variant(info, variant));
  path->frame();
  return {path->result(), path->frame_stats()};
}

struct HalfQuadCase {
  const char* name;
  const char* variant;
  double power, distortion, ambient, scale;
  glm::dvec3 light_dir;  // direction the light travels
  double albedo, color, thickness, ambient_light;
  // The half result, or NaN when the variant must produce a non-finite value (marker + count).
  double expected;
};

void PrintTo(const HalfQuadCase& c, std::ostream* os) {
  *os << c.name << " " << c.variant;
}

std::string half_quad_scene(const HalfQuadCase& c) {
  char buf[2048];
  std::snprintf(buf, sizeof buf, R"({
    "image": {"width": 32, "height": 32},
    "camera": {"eye": [0, 0, 5], "target": [0, 0, 0], "projection": "orthographic", "height": 1,
               "near": 1, "far": 10},
    "ambient_light": [%.17g, %.17g, %.17g],
    "materials": {"m": {"albedo": [%.17g, %.17g, %.17g], "translucency": {"power": %.17g,
      "distortion": %.17g, "ambient": %.17g, "thickness": %.17g}}},
    "lights": [{"type": "directional", "direction": [%.17g, %.17g, %.17g],
                "color": [%.17g, %.17g, %.17g], "translucency_scale": %.17g}],
    "objects": [{"mesh": "quad.obj", "material": "m"}]
  })",
                c.ambient_light, c.ambient_light, c.ambient_light, c.albedo, c.albedo, c.albedo,
                c.power, c.distortion, c.ambient, c.thickness, c.light_dir.x, c.light_dir.y,
                c.light_dir.z, c.color, c.color, c.color, c.scale);
  return buf;
}

const double kNaN = std::nan("");

// N = V = +Z everywhere (orthographic camera, quad facing it). Half values of the constants:
// 0.2 -> 0.199951171875, 0.1 -> 0.0999755859375, 0.9 -> 0.89990234375, 0.8 -> 0.7998046875,
// 0.05 -> 0.04998779296875, 1.4427 -> 1.4423828125.
const HalfQuadCase kHalfQuadCases[] = {
    // Where half rounding shows (reference_test's backlit_p4, whose double answer is 0.41364):
    // L = (0,0,-1). H.z = -1 + 1*0.19995 = -0.80004883, exactly halfway between two halves:
    // ties to even give -0.7998046875, so t = 0.7998046875 (not 0.8). log2(t) = -0.322265625,
    // * 4 = -1.2890625, exp2 -> lobe 0.4091796875 (double 0.8^4 = 0.4096). * s 2 = 0.818359375,
    // + a 0.0999755859375 = 0.918334960938 -> 0.91845703125 (half), * att 1, * T 0.5 =
    // 0.459228515625, * albedo 0.89990234375 = 0.41326... -> 0.413330078125.
    {"pow_0_8_to_4", "pow=exact", 4, 0.2, 0.1, 2, {0, 0, 1}, 0.9, 1, 0.5, 0, 0.413330078125},
    // The same with the spherical Gaussian: n' = 4 * 1.4423828125 + 1.4423828125 = 7.2109375;
    // t * n' - n' = -1.4453125; exp2 -> 0.3671875 (the SG curve, not 0.4096). * s 2 = 0.734375,
    // + 0.0999755859375 = 0.83435058594 -> 0.83447265625; * T 0.5 = 0.417236328125;
    // * albedo 0.89990234375 = 0.37547... -> 0.37548828125.
    {"sg_0_8_to_4", "pow=sg", 4, 0.2, 0.1, 2, {0, 0, 1}, 0.9, 1, 0.5, 0, 0.37548828125},
    // Underflow: d = 0.5 gives t = 0.5 exactly; log2 = -1, * 1024 = -1024, exp2(-1024) = 0 in
    // half (below the smallest subnormal 2^-24). c = 0.04998779296875 + (0 * 3 + 0.25) *
    // 0.7998046875 = 0.04998779296875 + 0.199951171875 = 0.24993896484 -> 0.25 (half).
    {"pow_half_1024_underflows", "pow=exact", 1024, 0.5, 0.25, 3, {0, 0, 1}, 1, 1, 0.8, 0.05, 0.25},
    // SG underflows too: n' = 1024 * 1.4423828125 + 1.4423828125 = 1478 (half);
    // 0.5 * 1478 - 1478 = -739, exp2 -> 0. Same 0.25.
    {"sg_1024_underflows", "pow=sg", 1024, 0.5, 0.25, 3, {0, 0, 1}, 1, 1, 0.8, 0.05, 0.25},
    // Saturating sum: t = 1, lobe = exp2(8 * log2(1)) = 1, * s 10000 = 10000 (a half), * color 8
    // = 80000 > 65504: the guarded variants saturate to 65504 (the largest finite half) ...
    {"overflow_saturates", "pow=exact", 8, 0, 0, 10000, {0, 0, 1}, 1, 8, 1, 0, 65504},
    {"overflow_saturates_sg", "pow=sg", 8, 0, 0, 10000, {0, 0, 1}, 1, 8, 1, 0, 65504},
    // ... and IEEE half rounds it to Inf: counted and drawn as the marker.
    {"overflow_unguarded", "pow=unguarded", 8, 0, 0, 10000, {0, 0, 1}, 1, 8, 1, 0, kNaN},
    // 0^0: front light L = (0,0,1), diffuse 1; t = saturate(-1) = 0, p = 0: guarded lobe 1.
    // c = 0.5 * (1 + (1 * 1 + 0) * 1) = 1 (the reference's value).
    {"zero_pow_zero", "pow=exact", 0, 0, 0, 1, {0, 0, -1}, 0.5, 1, 1, 0, 1.0},
    {"zero_pow_zero_sg", "pow=sg", 0, 0, 0, 1, {0, 0, -1}, 0.5, 1, 1, 0, 1.0},
    // Unguarded: exp2(0 * log2(0)) = exp2(0 * -Inf) = exp2(NaN) = NaN.
    {"zero_pow_zero_unguarded", "pow=unguarded", 0, 0, 0, 1, {0, 0, -1}, 0.5, 1, 1, 0, kNaN},
};

class HalfQuad : public ::testing::TestWithParam<HalfQuadCase> {};

TEST_P(HalfQuad, EveryCoveredPixelHasTheHandComputedHalfValue) {
  const HalfQuadCase& c = GetParam();
  test::TempDir dir;
  test::write_file(dir / "quad.obj", test::quad_obj());
  const Scene scene = load_scene(parse_scene(half_quad_scene(c), dir / "quad.json", dir.path()));
  const Rendered r = render_half(scene, c.variant);
  const bool marker = std::isnan(c.expected);
  EXPECT_EQ(r.stats.nonfinite_pixels.value(), marker ? 32.0 * 32.0 : 0.0);
  EXPECT_EQ(test::non_finite(r.image), 0u) << "no NaN or Inf ever reaches an image";
  for (int y = 0; y < r.image.height; ++y) {
    for (int x = 0; x < r.image.width; ++x) {
      const float* p = r.image.at(x, y);
      ASSERT_EQ(p[3], 1.0f) << "pixel " << x << "," << y << " not covered";
      // Every input is the same at every pixel and the arithmetic is binary16: the result is
      // one exact half value, so equality (the G-buffer's float noise vanishes when rounded).
      if (marker) {
        ASSERT_EQ(p[0], 1.0f);  // magenta marker (1, 0, 1)
        ASSERT_EQ(p[1], 0.0f);
        ASSERT_EQ(p[2], 1.0f);
      } else {
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_EQ(p[ch], static_cast<float>(c.expected))
              << c.name << " pixel " << x << "," << y << " channel " << ch;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Analytic, HalfQuad, ::testing::ValuesIn(kHalfQuadCases),
                         [](const auto& info) { return std::string(info.param.name); });

// Every variant on every demo scene against the reference: src/paths/bounds/path_bounds.json
// (bounds_test.cpp).

// Hard scenes: the guarded variants never produce a non-finite value (nothing to hide behind the
// marker); paths_test.cpp checks the images of every variant for NaN/Inf.
class HalfHardScene : public ::testing::TestWithParam<std::string> {};

TEST_P(HalfHardScene, GuardedVariantsProduceNoNonFinitePixel) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  for (const char* v : {"pow=exact", "pow=sg"}) {
    EXPECT_EQ(render_half(scene, v).stats.nonfinite_pixels.value(), 0.0) << v;
  }
}

INSTANTIATE_TEST_SUITE_P(Hard, HalfHardScene, ::testing::ValuesIn(test::json_files("scenes/hard")),
                         [](const auto& info) { return test::scene_param_name(info.param); });

size_t count_marker(const Image& img) {
  size_t n = 0;
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    const float* p = &img.rgba[i * 4];
    n += p[0] == 1.0f && p[1] == 0.0f && p[2] == 1.0f && p[3] == 1.0f;
  }
  return n;
}

// 0^0 on a sphere (p = 0): every pixel with t = 0 for some light gets exp2(0 * -Inf) = NaN.
TEST(HalfUnguarded, ZeroPowZeroIsCountedAndMarked) {
  const Scene scene = load_scene(test::source_dir() / "scenes/hard/zero_pow_zero.json");
  const Rendered r = render_half(scene, "pow=unguarded");
  EXPECT_EQ(test::non_finite(r.image), 0u);
  EXPECT_GT(r.stats.nonfinite_pixels.value(), 0.0);
  EXPECT_EQ(static_cast<double>(count_marker(r.image)), r.stats.nonfinite_pixels.value());
}

// A point light at the quad's centre vertex with kc = kl = 0: att = 1 / (dist^2) overflows half
// (1/dist^2 > 65504) when a pixel centre is within 1/sqrt(65504) = 0.0039 of the light. At the
// scene's 160x120 the nearest pixel centre is 0.017 away (pixel 0.024), so nothing overflows;
// at 1280x720 (the bench size) the four centre pixels are 0.0029 away: att = Inf, and
// Inf * 0 (the in-plane diffuse) = NaN. The guarded variants clamp att to 65504 there.
TEST(HalfUnguarded, PointLightAtVertexOverflowsAttenuation) {
  const Scene scene = load_scene(test::source_dir() / "scenes/hard/point_light_at_vertex.json");
  const Rendered r = render_half(scene, "pow=unguarded", 1280, 720);
  EXPECT_EQ(test::non_finite(r.image), 0u);
  EXPECT_EQ(r.stats.nonfinite_pixels.value(), 4.0);
  EXPECT_EQ(count_marker(r.image), 4u);
  EXPECT_EQ(render_half(scene, "pow=exact", 1280, 720).stats.nonfinite_pixels.value(), 0.0);
}

}  // namespace
}  // namespace lt
