// Every path against the reference on every scene of scenes/ and scenes/hard/ (one process per
// test, so a GL crash fails one case). Thresholds are stated per case with their reason.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "load/load_scene.h"
#include "metrics/compare.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

// glsl against the reference. Both rasterise the same float G-buffer inputs (same transform,
// same interpolation); glsl shades in float with exact pow. Measured: the float target is within
// 5e-4 LSB of the reference on every scene (`ltrender bench scenes/*.json scenes/hard/*.json
// --paths glsl`), so its bar (0.01 max, 0.001 mean) is 100x looser than measured and 100x
// tighter than the 1 LSB / 0.1 LSB. The 8-bit default adds one rounding: every pixel
// must round to the nearest 8-bit value of the reference, max 0.5 LSB plus that float error.
// (Its mean is the rounding's own, ~0.25 LSB on gradients, anything in [0, 0.5] on flat areas:
// no 8-bit output can have a mean of 0.1 against a float reference, so the mean bar is checked
// on the float target.)
constexpr double kGlslF32MaxLsb = 0.01, kGlslF32MeanLsb = 0.001;
constexpr double kGlslU8MaxLsb = 0.5 + kGlslF32MaxLsb;

void expect_glsl_matches(const Scene& scene, const Image& ref) {
  const Image u8 = render_scene(scene, "glsl", "pow=exact");
  const Comparison c8 = compare_images(u8, ref, TestEncoding::kUnorm8);
  EXPECT_EQ(c8.test_non_finite, 0u);
  EXPECT_LE(c8.covered.max_lsb, kGlslU8MaxLsb)
      << "8-bit at " << c8.covered.max_x << "," << c8.covered.max_y;
  // Background and coverage agree too: the same rasteriser drew both.
  EXPECT_LE(c8.image.max_lsb, kGlslU8MaxLsb);
  const Image f32 = render_scene(scene, "glsl", "pow=exact:f32");
  const Comparison cf = compare_images(f32, ref, TestEncoding::kFloat);
  EXPECT_EQ(cf.test_non_finite, 0u);
  EXPECT_LE(cf.covered.max_lsb, kGlslF32MaxLsb)
      << "f32 at " << cf.covered.max_x << "," << cf.covered.max_y;
  EXPECT_LE(cf.covered.mean_lsb, kGlslF32MeanLsb);
}

// The demo scenes: src/paths/bounds/path_bounds.json (bounds_test.cpp).

class HardSceneGlsl : public ::testing::TestWithParam<std::string> {};

TEST_P(HardSceneGlsl, GlslMatchesReference) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  expect_glsl_matches(scene, render_scene(scene, "reference", ""));
}

INSTANTIATE_TEST_SUITE_P(Hard, HardSceneGlsl, ::testing::ValuesIn(test::json_files("scenes/hard")),
                         [](const auto& info) { return test::scene_param_name(info.param); });

// Every hard case of model.md on every path and every variant: no NaN or Inf reaches an image,
// and the case shows something. Accuracy is bounded per path where its error is explained
// (above for glsl, arbfp_test.cpp, combiners_test.cpp).
struct HardCase {
  std::string scene, path, variant;
};

// gtest prints parameters; a name reads better in ctest than the struct's bytes.
void PrintTo(const HardCase& c, std::ostream* os) {
  *os << c.scene << " " << c.path << " " << c.variant;
}

std::vector<HardCase> hard_cases() {
  std::vector<HardCase> out;
  for (const auto& s : test::json_files("scenes/hard")) {
    for (const PathInfo& p : all_paths()) {
      for (const VariantInfo& v : p.variants) out.push_back({s, p.name, v.name});
    }
  }
  return out;
}

class HardScene : public ::testing::TestWithParam<HardCase> {};

TEST_P(HardScene, NoNanOrInfReachesTheImage) {
  const HardCase& hc = GetParam();
  const Scene scene = load_scene(test::source_dir() / hc.scene);
  const PathInfo& info = find_path(hc.path);
  // A variant that cannot be exact here is refused by render (tested in gx_path_test.cpp).
  if (!info.refusal(scene, hc.variant).empty()) GTEST_SKIP() << info.refusal(scene, hc.variant);
  const Image img = render_scene(scene, hc.path, hc.variant);
  EXPECT_EQ(test::non_finite(img), 0u) << hc.path << " " << hc.variant;
  EXPECT_GT(test::covered_pixels(img), 0u) << "the hard case shows nothing";
}

INSTANTIATE_TEST_SUITE_P(Hard, HardScene, ::testing::ValuesIn(hard_cases()), [](const auto& info) {
  std::string v = info.param.variant;
  for (char& c : v) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return test::scene_param_name(info.param.scene) + "__" + info.param.path + "__" + v;
});

}  // namespace
}  // namespace lt

namespace lt {
namespace {

// Variants that are a grammar reach the command line whole: any LUT the generator builds, in
// its canonical spelling, and nothing else.
TEST(VariantGrammar, PathsWithAGrammarAcceptEveryValidCombination) {
  EXPECT_EQ(resolve_variant(find_path("arbfp"), "pow=lut:128:f16"), "pow=lut:128:f16");
  EXPECT_EQ(resolve_variant(find_path("gx"), "lut=64:t=vertex"), "t=vertex:lut=64");
  EXPECT_EQ(resolve_variant(find_path("gx"), ""), "t=vertex");
  for (const auto& [path, bad] :
       std::vector<std::pair<std::string, std::string>>{{"arbfp", "pow=lut:1:f16"},
                                                        {"arbfp", "pow=lut:64:f8"},
                                                        {"gx", "t=vertex:lut=0"},
                                                        {"glsl", "pow=lut:64:u8"},
                                                        {"half", "pow=mul"}}) {
    EXPECT_THROW(resolve_variant(find_path(path), bad), InputError) << path << " " << bad;
  }
}

}  // namespace
}  // namespace lt
