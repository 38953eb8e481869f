// Image metrics (metrics/compare.h, metrics/heatmap.h) and `ltrender compare`. Every expectation
// is worked out by hand from the formula of metrics.md, e = |O/255 - clamp(R, 0, 1)| * 255.
#include "metrics/compare.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "core/build_paths.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/stderr_capture.h"
#include "image/image.h"
#include "metrics/heatmap.h"
#include "test_util.h"

namespace lt {
namespace {

namespace fs = std::filesystem;

Image filled(int w, int h, float r, float g, float b, float a = 1.0f) {
  Image img(w, h);
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    img.rgba[i * 4 + 0] = r, img.rgba[i * 4 + 1] = g, img.rgba[i * 4 + 2] = b;
    img.rgba[i * 4 + 3] = a;
  }
  return img;
}

// The value an 8-bit file holds for byte k, as read_image returns it.
float byte(int k) {
  return static_cast<float>(k) / 255.0f;
}

// ---------------------------------------------------------------------------------------------
// The per-channel formula.

TEST(CompareFormula, EightBitIsStoredByteAgainstClampedReference) {
  // 128/255 vs 0.5: |128 - 127.5| = 0.5 LSB, the rounding floor.
  EXPECT_DOUBLE_EQ(channel_error_lsb(byte(128), 0.5f, TestEncoding::kUnorm8), 0.5);
  EXPECT_DOUBLE_EQ(channel_error_lsb(byte(10), 0.0f, TestEncoding::kUnorm8), 10.0);
  // The reference is clamped: white shows 1.7 as well as it can be shown.
  EXPECT_DOUBLE_EQ(channel_error_lsb(byte(255), 1.7f, TestEncoding::kUnorm8), 0.0);
  EXPECT_DOUBLE_EQ(channel_error_lsb(byte(0), -0.3f, TestEncoding::kUnorm8), 0.0);
  // An in-memory float judged as 8-bit is quantised like write_image does: 0.3 -> 77.
  EXPECT_NEAR(channel_error_lsb(0.3f, 0.3f, TestEncoding::kUnorm8), std::abs(77.0 - 76.5), 1e-5);
}

TEST(CompareFormula, FloatIsUnquantisedAndClampedOnBothSides) {
  EXPECT_NEAR(channel_error_lsb(0.5f, 0.25f, TestEncoding::kFloat), 63.75, 1e-9);
  // A quarter of an LSB survives: no quantisation on the float side.
  EXPECT_NEAR(channel_error_lsb(0.5f + 0.25f / 255.0f, 0.5f, TestEncoding::kFloat), 0.25, 1e-4);
  // Both sides clamped: overshoot beyond the displayed range is not error.
  EXPECT_DOUBLE_EQ(channel_error_lsb(1.2f, 1.0f, TestEncoding::kFloat), 0.0);
  EXPECT_DOUBLE_EQ(channel_error_lsb(1.2f, 3.0f, TestEncoding::kFloat), 0.0);
  EXPECT_DOUBLE_EQ(channel_error_lsb(-0.1f, 0.0f, TestEncoding::kFloat), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Figures of compare_images.

TEST(CompareMetrics, RoundedReferenceIsWithinHalfAnLsb) {
  // A gradient with values between the 8-bit steps, and out-of-range values at the ends.
  Image ref(97, 13), test(97, 13);
  for (int y = 0; y < ref.height; ++y) {
    for (int x = 0; x < ref.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        const float r = -0.05f + 1.1f * static_cast<float>(x * 3 + c + y * 0.37) / (97 * 3);
        ref.at(x, y)[c] = r;
        const double clamped = std::clamp(static_cast<double>(r), 0.0, 1.0);
        test.at(x, y)[c] = byte(static_cast<int>(std::lround(clamped * 255.0)));
      }
      ref.at(x, y)[3] = test.at(x, y)[3] = 1.0f;
    }
  }
  const Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  EXPECT_LE(cmp.image.max_lsb, 0.5);
  EXPECT_GT(cmp.image.max_lsb, 0.45);  // the gradient does fall between steps
  EXPECT_LE(cmp.image.mean_lsb, 0.5);
  EXPECT_EQ(cmp.image.percent_over_1_lsb, 0.0);
  EXPECT_EQ(cmp.image.pixels, 97u * 13u);
  EXPECT_EQ(cmp.covered.pixels, 97u * 13u);
  EXPECT_TRUE(apply_tolerance(cmp, Tolerance{}).pass);
}

TEST(CompareMetrics, SinglePixelOffsetGivesKnownFigures) {
  // 4x4 black reference; the test is black but for G = 10/255 at (2, 1).
  const Image ref = filled(4, 4, 0, 0, 0);
  Image test = filled(4, 4, 0, 0, 0);
  test.at(2, 1)[1] = byte(10);
  const Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  const ErrorStats& s = cmp.image;
  EXPECT_EQ(s.pixels, 16u);
  EXPECT_DOUBLE_EQ(s.max_lsb, 10.0);
  EXPECT_EQ(s.max_x, 2);
  EXPECT_EQ(s.max_y, 1);
  EXPECT_EQ(s.max_channel, 1);
  // 48 channel values, one of them 10.
  EXPECT_NEAR(s.mean_lsb, 10.0 / 48.0, 1e-12);
  EXPECT_NEAR(s.rmse_lsb, std::sqrt(100.0 / 48.0), 1e-12);  // 1.44338
  EXPECT_NEAR(s.psnr_db, 44.94321598, 1e-6);                // 20 log10(255 / 1.44338)
  // 16 pixel errors, fifteen 0 and one 10: nearest rank ceil(0.99 * 16) = 16 is the 10.
  EXPECT_DOUBLE_EQ(s.p99_lsb, 10.0);
  EXPECT_DOUBLE_EQ(s.percent_over_1_lsb, 6.25);
  EXPECT_DOUBLE_EQ(s.percent_over_4_lsb, 6.25);
  EXPECT_EQ(cmp.test_non_finite, 0u);
  EXPECT_DOUBLE_EQ(cmp.pixel_error_lsb[1 * 4 + 2], 10.0);
}

TEST(CompareMetrics, IdenticalImagesHaveInfinitePsnr) {
  const Image ref = filled(3, 2, 0.25f, 0.5f, 1.0f);
  const Comparison cmp = compare_images(ref, ref, TestEncoding::kFloat);
  EXPECT_EQ(cmp.image.max_lsb, 0.0);
  EXPECT_EQ(cmp.image.rmse_lsb, 0.0);
  EXPECT_TRUE(std::isinf(cmp.image.psnr_db));
  EXPECT_TRUE(std::isinf(cmp.covered.psnr_db));
  // JSON has no infinity: null, as compare.h documents.
  const auto j = to_json(cmp, Tolerance{}, apply_tolerance(cmp, Tolerance{}));
  EXPECT_TRUE(j["image"]["psnr_db"].is_null());
  EXPECT_TRUE(j["thresholds"]["hard_fail_lsb"].is_null());
}

TEST(CompareMetrics, PercentileIsNearestRankOverPixels) {
  // 100 pixels with errors 0..99 LSB (byte k against black, on R only).
  Image ref = filled(100, 1, 0, 0, 0), test = filled(100, 1, 0, 0, 0);
  for (int x = 0; x < 100; ++x) test.at(x, 0)[0] = byte(x);
  Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  // rank ceil(0.99 * 100) = 99 -> the 99th smallest, 98.
  EXPECT_DOUBLE_EQ(cmp.image.p99_lsb, 98.0);
  EXPECT_DOUBLE_EQ(cmp.image.percent_over_1_lsb, 98.0);  // 2..99
  EXPECT_DOUBLE_EQ(cmp.image.percent_over_4_lsb, 95.0);  // 5..99
  EXPECT_NEAR(cmp.image.mean_lsb, 4950.0 / 300.0, 1e-12);

  // 200 pixels, errors 0..199: rank 198 -> 197.
  ref = filled(200, 1, 0, 0, 0), test = filled(200, 1, 0, 0, 0);
  for (int x = 0; x < 200; ++x) test.at(x, 0)[2] = byte(x);
  cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  EXPECT_DOUBLE_EQ(cmp.image.p99_lsb, 197.0);
}

TEST(CompareMetrics, PixelFiguresUseTheWorstChannel) {
  // One pixel, errors R 2, G 5, B 3: the pixel counts once, as 5.
  const Image ref = filled(1, 1, 0, 0, 0);
  const Image test = filled(1, 1, byte(2), byte(5), byte(3));
  const Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  EXPECT_DOUBLE_EQ(cmp.image.p99_lsb, 5.0);
  EXPECT_DOUBLE_EQ(cmp.image.percent_over_4_lsb, 100.0);
  EXPECT_NEAR(cmp.image.mean_lsb, 10.0 / 3.0, 1e-12);
  EXPECT_EQ(cmp.image.max_channel, 1);
}

TEST(CompareMetrics, CoverageRestrictsTheCoveredFigures) {
  // 4x2: the reference covers the left two columns (alpha 1), not the right two (alpha 0).
  Image ref = filled(4, 2, 0, 0, 0), test = filled(4, 2, 0, 0, 0);
  for (int y = 0; y < 2; ++y) ref.at(2, y)[3] = ref.at(3, y)[3] = 0.0f;
  test.at(3, 0)[0] = byte(20);  // uncovered
  test.at(0, 1)[2] = byte(2);   // covered
  const Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  EXPECT_EQ(cmp.covered.pixels, 4u);
  EXPECT_DOUBLE_EQ(cmp.covered.max_lsb, 2.0);
  EXPECT_EQ(cmp.covered.max_x, 0);
  EXPECT_EQ(cmp.covered.max_y, 1);
  EXPECT_EQ(cmp.covered.max_channel, 2);
  EXPECT_NEAR(cmp.covered.mean_lsb, 2.0 / 12.0, 1e-12);
  EXPECT_DOUBLE_EQ(cmp.covered.percent_over_1_lsb, 25.0);
  EXPECT_DOUBLE_EQ(cmp.covered.percent_over_4_lsb, 0.0);

  EXPECT_EQ(cmp.image.pixels, 8u);
  EXPECT_DOUBLE_EQ(cmp.image.max_lsb, 20.0);
  EXPECT_EQ(cmp.image.max_x, 3);
  EXPECT_EQ(cmp.image.max_y, 0);
  EXPECT_NEAR(cmp.image.mean_lsb, 22.0 / 24.0, 1e-12);
  EXPECT_DOUBLE_EQ(cmp.image.percent_over_1_lsb, 25.0);
  EXPECT_DOUBLE_EQ(cmp.image.percent_over_4_lsb, 12.5);
}

TEST(CompareMetrics, CoverageIsAlphaOverOneHalf) {
  EXPECT_FALSE(is_covered(0.5f));
  EXPECT_TRUE(is_covered(0.5001f));
  EXPECT_FALSE(is_covered(0.0f));
  Image ref = filled(2, 1, 0, 0, 0, 0.5f);
  ref.at(1, 0)[3] = 0.75f;
  const Comparison cmp = compare_images(filled(2, 1, 0.5f, 0, 0), ref, TestEncoding::kFloat);
  EXPECT_EQ(cmp.covered.pixels, 1u);
  EXPECT_EQ(cmp.covered.max_x, 1);  // the same error on both: the covered one is pixel 1
}

TEST(CompareMetrics, EmptyCoverageHasNoFigures) {
  const Image ref = filled(2, 2, 0, 0, 0, 0.0f);
  const Image test = filled(2, 2, 1, 1, 1);
  const Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  EXPECT_EQ(cmp.covered.pixels, 0u);
  EXPECT_EQ(cmp.covered.max_channel, -1);
  EXPECT_EQ(cmp.covered.max_lsb, 0.0);
  EXPECT_DOUBLE_EQ(cmp.image.max_lsb, 255.0);
  EXPECT_TRUE(apply_tolerance(cmp, Tolerance{}).pass);  // nothing covered, nothing to fail
  Tolerance whole;
  whole.region = Region::kImage;
  EXPECT_FALSE(apply_tolerance(cmp, whole).pass);
}

TEST(CompareMetrics, NonFiniteTestPixelsAreCountedAndLeftOut) {
  const Image ref = filled(3, 1, 0.5f, 0.5f, 0.5f);
  Image test = ref;
  test.at(0, 0)[1] = std::numeric_limits<float>::quiet_NaN();
  test.at(2, 0)[2] = std::numeric_limits<float>::infinity();
  test.at(2, 0)[3] = -std::numeric_limits<float>::infinity();
  const Comparison cmp = compare_images(test, ref, TestEncoding::kFloat);
  EXPECT_EQ(cmp.test_non_finite, 3u);
  EXPECT_EQ(cmp.test_non_finite_pixels, 2u);
  EXPECT_EQ(cmp.image.pixels, 1u);
  EXPECT_EQ(cmp.image.max_lsb, 0.0);
  EXPECT_TRUE(std::isnan(cmp.pixel_error_lsb[0]));

  // Whatever the tolerance, a non-finite value fails.
  Tolerance lenient;
  lenient.fail_lsb = 255.0;
  lenient.fail_percent = 100.0;
  const Verdict v = apply_tolerance(cmp, lenient);
  EXPECT_FALSE(v.pass);
  ASSERT_EQ(v.reasons.size(), 1u);
  EXPECT_NE(v.reasons[0].find("non-finite"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Thresholds (judge).

// 4x4 black reference, test black but one pixel with `lsb` on R.
Comparison one_pixel_off(int lsb) {
  const Image ref = filled(4, 4, 0, 0, 0);
  Image test = ref;
  test.at(1, 3)[0] = byte(lsb);
  return compare_images(test, ref, TestEncoding::kUnorm8);
}

TEST(CompareJudge, FailLsbIsStrictlyGreater) {
  const Comparison cmp = one_pixel_off(1);        // exactly 1.0 LSB
  Verdict v = apply_tolerance(cmp, Tolerance{});  // default: fail_lsb 1, fail_percent 0
  EXPECT_TRUE(v.pass);
  EXPECT_EQ(v.failing_pixels, 0u);

  Tolerance tight;
  tight.fail_lsb = 0.99;
  v = apply_tolerance(cmp, tight);
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.failing_pixels, 1u);
  EXPECT_DOUBLE_EQ(v.failing_percent, 6.25);
  EXPECT_FALSE(v.reasons.empty());
}

TEST(CompareJudge, FailPercentBoundary) {
  const Comparison cmp = one_pixel_off(10);  // 1 of 16 pixels = 6.25% over 1 LSB
  Tolerance t;
  t.fail_percent = 6.25;
  EXPECT_TRUE(apply_tolerance(cmp, t).pass);  // "more than P percent" fails, exactly P passes
  t.fail_percent = 6.2;
  EXPECT_FALSE(apply_tolerance(cmp, t).pass);
  t.fail_percent = 0.0;
  t.fail_lsb = 10.0;
  EXPECT_TRUE(apply_tolerance(cmp, t).pass);
}

TEST(CompareJudge, HardFailIsAnyPixel) {
  const Comparison cmp = one_pixel_off(10);
  Tolerance t;
  t.fail_percent = 100.0;
  t.hard_fail_lsb = 10.0;
  EXPECT_TRUE(apply_tolerance(cmp, t).pass);
  t.hard_fail_lsb = 9.99;
  const Verdict v = apply_tolerance(cmp, t);
  EXPECT_FALSE(v.pass);
  EXPECT_EQ(v.hard_failing_pixels, 1u);
  ASSERT_EQ(v.reasons.size(), 1u);
  EXPECT_NE(v.reasons[0].find("1,3 R"), std::string::npos) << v.reasons[0];
}

TEST(CompareJudge, RegionPicksWhichPixelsAreJudged) {
  // The only error is where the reference has no coverage.
  Image ref = filled(2, 1, 0, 0, 0), test = filled(2, 1, 0, 0, 0);
  ref.at(1, 0)[3] = 0.0f;
  test.at(1, 0)[0] = byte(50);
  const Comparison cmp = compare_images(test, ref, TestEncoding::kUnorm8);
  Tolerance t;
  EXPECT_TRUE(apply_tolerance(cmp, t).pass);
  t.region = Region::kImage;
  const Verdict v = apply_tolerance(cmp, t);
  EXPECT_FALSE(v.pass);
  EXPECT_DOUBLE_EQ(v.failing_percent, 50.0);
}

// ---------------------------------------------------------------------------------------------
// Heatmap.

void expect_rgb(const float* got, float r, float g, float b) {
  EXPECT_NEAR(got[0], r, 1e-6);
  EXPECT_NEAR(got[1], g, 1e-6);
  EXPECT_NEAR(got[2], b, 1e-6);
}

TEST(CompareHeatmap, RampStops) {
  float rgb[3];
  heatmap_colour(0.0, 8.0, rgb), expect_rgb(rgb, 0, 0, 0);
  heatmap_colour(0.8, 8.0, rgb), expect_rgb(rgb, 0, 0, 0.5f);  // halfway to blue
  heatmap_colour(1.6, 8.0, rgb), expect_rgb(rgb, 0, 0, 1);
  heatmap_colour(3.2, 8.0, rgb), expect_rgb(rgb, 0, 1, 0);
  heatmap_colour(4.8, 8.0, rgb), expect_rgb(rgb, 1, 1, 0);
  heatmap_colour(6.4, 8.0, rgb), expect_rgb(rgb, 1, 0, 0);
  heatmap_colour(8.0, 8.0, rgb), expect_rgb(rgb, 1, 1, 1);
  heatmap_colour(100.0, 8.0, rgb), expect_rgb(rgb, 1, 1, 1);
}

TEST(CompareHeatmap, CoverageAndNonFiniteAreVisible) {
  // (0,0) covered exact, (1,0) uncovered exact, (2,0) uncovered 8 LSB, (3,0) NaN,
  // (4,0) covered 1.6 LSB (float test).
  Image ref = filled(5, 1, 0, 0, 0), test = filled(5, 1, 0, 0, 0);
  ref.at(1, 0)[3] = ref.at(2, 0)[3] = 0.0f;
  test.at(2, 0)[1] = byte(8);
  test.at(3, 0)[0] = std::numeric_limits<float>::quiet_NaN();
  test.at(4, 0)[2] = 1.6f / 255.0f;
  const Image heat = error_heatmap(compare_images(test, ref, TestEncoding::kFloat), 8.0);
  ASSERT_EQ(heat.width, 5);
  ASSERT_EQ(heat.height, 1);
  expect_rgb(heat.at(0, 0), 0, 0, 0);
  expect_rgb(heat.at(1, 0), kHeatmapUncovered[0], kHeatmapUncovered[1], kHeatmapUncovered[2]);
  expect_rgb(heat.at(2, 0), 1, 1, 1);
  expect_rgb(heat.at(3, 0), kHeatmapNonFinite[0], kHeatmapNonFinite[1], kHeatmapNonFinite[2]);
  EXPECT_NEAR(heat.at(4, 0)[2], 1.0f, 1e-4);
  EXPECT_EQ(heat.at(4, 0)[3], 1.0f);
}

// ---------------------------------------------------------------------------------------------
// Files: encoding detection and reading.

class CompareFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("ltrender_compare_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(CompareFiles, EncodingComesFromTheTestFile) {
  const Image img = filled(4, 4, 0.5f, 0.25f, 1.0f);
  write_image(path("a.png"), img);
  write_image(path("a.exr"), img);
  EXPECT_EQ(encoding_of(path("a.png")), TestEncoding::kUnorm8);
  EXPECT_EQ(encoding_of(path("a.exr")), TestEncoding::kFloat);
  EXPECT_THROW(encoding_of(path("missing.png")), InputError);
}

TEST_F(CompareFiles, PngOfReferenceIsWithinHalfAnLsb) {
  Image ref(16, 16);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) {
      float* p = ref.at(x, y);
      p[0] = static_cast<float>(x) / 15.3f, p[1] = static_cast<float>(y) / 17.1f;
      p[2] = 0.3337f, p[3] = x < 8 ? 1.0f : 0.0f;
    }
  }
  write_image(path("ref.exr"), ref);
  write_image(path("test.png"), ref);
  const Comparison cmp = compare_files(path("test.png"), path("ref.exr"));
  EXPECT_EQ(cmp.encoding, TestEncoding::kUnorm8);
  EXPECT_LE(cmp.image.max_lsb, 0.5 + 1e-4);  // to_unorm8 rounds in float
  EXPECT_EQ(cmp.covered.pixels, 128u);       // the EXR's alpha is the coverage

  // The EXR against itself, float: exact.
  const Comparison self = compare_files(path("ref.exr"), path("ref.exr"));
  EXPECT_EQ(self.encoding, TestEncoding::kFloat);
  EXPECT_EQ(self.image.max_lsb, 0.0);
}

// Issue 24: `compare a.png a.png` printed a PSNR of 159 dB and a max location for no error: an
// 8-bit reference is compared as its bytes, so identical files have no error at all.
TEST_F(CompareFiles, IdenticalEightBitFilesHaveNoErrorAndNoMaxLocation) {
  Image img(16, 4);
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 16; ++x) {
      float* p = img.at(x, y);
      p[0] = byte(x * 16 + y), p[1] = byte(255 - x * 16), p[2] = byte(3 * x + 7 * y), p[3] = 1;
    }
  }
  write_image(path("a.png"), img);
  const Comparison cmp = compare_files(path("a.png"), path("a.png"));
  for (const ErrorStats* s : {&cmp.covered, &cmp.image}) {
    EXPECT_EQ(s->max_lsb, 0.0);
    EXPECT_EQ(s->rmse_lsb, 0.0);
    EXPECT_TRUE(std::isinf(s->psnr_db));
    EXPECT_EQ(s->max_channel, -1);
    EXPECT_EQ(s->max_x, -1);
  }
  const Verdict v = apply_tolerance(cmp, Tolerance{});
  const std::string table = to_table(cmp, Tolerance{}, v);
  EXPECT_NE(table.find("PSNR dB                   inf            inf"), std::string::npos) << table;
  EXPECT_NE(table.find("  at x,y ch                 -              -"), std::string::npos) << table;
  const auto j = to_json(cmp, Tolerance{}, v);
  EXPECT_TRUE(j["image"]["psnr_db"].is_null());
  EXPECT_TRUE(j["image"]["max_at"].is_null());

  // One byte off against an 8-bit reference is 1 LSB exactly, so not over --fail-lsb 1 (the
  // float k/255 made it 1 +- 8e-6, over it about half the time).
  Image step = img;
  for (int x = 0; x < 16; ++x) step.at(x, 0)[1] = byte(256 - x * 16 - (x == 0 ? 2 : 0));
  write_image(path("step.png"), step);
  const Comparison one = compare_files(path("step.png"), path("a.png"));
  EXPECT_EQ(one.image.max_lsb, 1.0);
  EXPECT_EQ(apply_tolerance(one, Tolerance{}).failing_pixels, 0u);
}

TEST_F(CompareFiles, ReferenceWithoutAlphaIsAllCovered) {
  write_image(path("ref.png"), filled(5, 3, 0.5f, 0.5f, 0.5f, 0.0f));  // PNG drops alpha
  const Comparison cmp = compare_files(path("ref.png"), path("ref.png"));
  EXPECT_EQ(cmp.covered.pixels, 15u);
}

TEST_F(CompareFiles, FloatTestIsNotQuantised) {
  const Image ref = filled(2, 2, 0.5f, 0.5f, 0.5f);
  write_image(path("ref.exr"), ref);
  write_image(path("test.exr"), filled(2, 2, 0.5f + 0.25f / 255.0f, 0.5f, 0.5f));
  write_image(path("test.png"), filled(2, 2, 0.5f + 0.25f / 255.0f, 0.5f, 0.5f));
  EXPECT_NEAR(compare_files(path("test.exr"), path("ref.exr")).image.max_lsb, 0.25, 1e-4);
  // The same values through 8 bits: 127.75 -> 128, all channels 0.5 LSB from 127.5.
  EXPECT_NEAR(compare_files(path("test.png"), path("ref.exr")).image.max_lsb, 0.5, 1e-6);
}

TEST_F(CompareFiles, BadInputIsInputError) {
  write_image(path("a.exr"), filled(4, 4, 0, 0, 0));
  write_image(path("b.exr"), filled(8, 4, 0, 0, 0));
  Image nan_ref = filled(4, 4, 0, 0, 0);
  nan_ref.at(1, 2)[0] = std::numeric_limits<float>::quiet_NaN();
  write_image(path("nan.exr"), nan_ref);
  try {
    compare_files(path("a.exr"), path("b.exr"));
    FAIL() << "size mismatch accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("4x4"), std::string::npos) << what;
    EXPECT_NE(what.find("8x4"), std::string::npos) << what;
  }
  EXPECT_THROW(compare_files(path("missing.png"), path("a.exr")), InputError);
  EXPECT_THROW(compare_files(path("a.exr"), path("missing.exr")), InputError);
  EXPECT_THROW(compare_files(path("a.exr"), path("nan.exr")), InputError);
}

// Only four channels are read whatever the file declares; an alpha channel beyond them (a TIFF
// with an extra sample before alpha) is still the coverage.
TEST_F(CompareFiles, AlphaBeyondTheFourthChannelIsStillCoverage) {
  auto out = OIIO::ImageOutput::create(path("five.tif"));
  ASSERT_TRUE(out);
  OIIO::ImageSpec spec(2, 1, 5, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B", "X", "A"};
  spec.alpha_channel = 4;
  const float pixels[10] = {0.1f, 0.2f, 0.3f, 9.0f, 1.0f, 0.4f, 0.5f, 0.6f, 9.0f, 0.0f};
  ASSERT_TRUE(out->open(path("five.tif"), spec) && out->write_image(OIIO::TypeDesc::FLOAT, pixels));
  out->close();
  const Image img = read_image(path("five.tif"));
  ASSERT_EQ(img.width, 2);
  EXPECT_EQ(img.at(0, 0)[0], 0.1f);
  EXPECT_EQ(img.at(0, 0)[3], 1.0f);
  EXPECT_EQ(img.at(1, 0)[2], 0.6f);
  EXPECT_EQ(img.at(1, 0)[3], 0.0f);
}

TEST(StderrCapture, FoldsWhatALibraryPrintedUnlessTheMessageSaysIt) {
  {
    StderrCapture capture;
    std::fprintf(stderr, "libfoo error: bad chunk\n\n");
    EXPECT_EQ(capture.fold_into("cannot read image"),
              "cannot read image [libfoo error: bad chunk]");
  }
  {
    StderrCapture capture;
    std::fprintf(stderr, "libpng error: IDAT: hit end of file\n");
    EXPECT_EQ(capture.fold_into("cannot decode image: PNG read error: IDAT: hit end of file"),
              "cannot decode image: PNG read error: IDAT: hit end of file");
  }
  // Not taken (the call succeeded): passed on to stderr unchanged.
  ::testing::internal::CaptureStderr();
  {
    StderrCapture capture;
    std::fprintf(stderr, "libpng warning: iCCP: known incorrect sRGB profile\n");
  }
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            "libpng warning: iCCP: known incorrect sRGB profile\n");
}

// ---------------------------------------------------------------------------------------------
// The command line, through the built binary.

struct CliResult {
  int code = -1;
  std::string out, err;
};

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

class CompareCli : public CompareFiles {
 protected:
  CliResult run(const std::string& args) {
    const std::string out = path("stdout.txt"), err = path("stderr.txt");
    const std::string cmd = "'" + lt::build_paths::ltrender_binary().string() + "' compare " +
                            args + " >'" + out + "' 2>'" + err + "'";
    const int status = std::system(cmd.c_str());
    CliResult r;
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    r.out = read_all(out);
    r.err = read_all(err);
    return r;
  }

  std::string q(const std::string& name) const { return "'" + path(name) + "'"; }

  // 8x8 reference with the right half uncovered; a PNG equal to it; a PNG with one covered
  // pixel 10 LSB off.
  void write_scene() {
    Image ref(8, 8);
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        float* p = ref.at(x, y);
        p[0] = 0.1f * static_cast<float>(x), p[1] = 0.37f, p[2] = 0.05f * static_cast<float>(y);
        p[3] = x < 4 ? 1.0f : 0.0f;
      }
    }
    write_image(path("ref.exr"), ref);
    write_image(path("same.png"), ref);
    Image off = ref;
    off.at(1, 1)[1] += 10.0f / 255.0f;
    write_image(path("off.png"), off);
  }
};

TEST_F(CompareCli, MatchingImagesPass) {
  write_scene();
  const CliResult r = run(q("same.png") + " " + q("ref.exr"));
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("PASS"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("covered"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST_F(CompareCli, JsonHasEveryFigure) {
  write_scene();
  CliResult r = run(q("off.png") + " " + q("ref.exr") + " --json --fail-lsb 12");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);  // stdout is only the object
  EXPECT_EQ(j["encoding"], "unorm8");
  EXPECT_EQ(j["width"], 8);
  EXPECT_EQ(j["pass"], true);
  for (const char* region : {"covered", "image"}) {
    for (const char* key : {"pixels", "max_lsb", "max_at", "mean_lsb", "rmse_lsb", "psnr_db",
                            "p99_lsb", "percent_over_1_lsb", "percent_over_4_lsb"}) {
      EXPECT_TRUE(j[region].contains(key)) << region << "." << key;
    }
  }
  EXPECT_EQ(j["covered"]["pixels"], 32);
  EXPECT_EQ(j["image"]["pixels"], 64);
  EXPECT_NEAR(j["covered"]["max_lsb"].get<double>(), 10.0, 0.51);  // 10 LSB plus rounding
  EXPECT_EQ(j["covered"]["max_at"]["x"], 1);
  EXPECT_EQ(j["covered"]["max_at"]["y"], 1);
  EXPECT_EQ(j["covered"]["max_at"]["channel"], "G");
  EXPECT_EQ(j["thresholds"]["fail_lsb"], 12.0);
  EXPECT_EQ(j["thresholds"]["fail_percent"], 0.0);
  EXPECT_TRUE(j["thresholds"]["hard_fail_lsb"].is_null());  // infinity
  EXPECT_EQ(j["test_non_finite"], 0);

  // Identical float images: PSNR is infinite, written as null.
  r = run(q("ref.exr") + " " + q("ref.exr") + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json self = nlohmann::json::parse(r.out);
  EXPECT_EQ(self["encoding"], "float");
  EXPECT_TRUE(self["covered"]["psnr_db"].is_null());
  EXPECT_EQ(self["covered"]["max_lsb"], 0.0);
}

// Issue 24: `compare REF TEST` swapped was silently accepted.
TEST_F(CompareCli, SwappedArgumentsAreRefusedWithTheRightOrder) {
  write_scene();
  const CliResult r = run(q("ref.exr") + " " + q("same.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "ltrender: error: " + path("same.png") + ": REF is an 8-bit image and TEST " +
                       path("ref.exr") +
                       " a float one: the float reference comes second (ltrender compare " +
                       path("same.png") + " " + path("ref.exr") + ")\n");
  // Two 8-bit files (a render against a golden) and two float files are compared as given.
  EXPECT_EQ(run(q("same.png") + " " + q("off.png") + " --fail-lsb 20").code, 0);
  EXPECT_EQ(run(q("ref.exr") + " " + q("ref.exr")).code, 0);
}

TEST_F(CompareCli, OverThresholdExitsOne) {
  write_scene();
  const CliResult r = run(q("off.png") + " " + q("ref.exr"));
  EXPECT_EQ(r.code, 1);
  EXPECT_NE(r.out.find("FAIL"), std::string::npos) << r.out;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ltrender: check failed: ", 0), 0u) << r.err;

  // 1 of 32 covered pixels = 3.125%: allowed at 3.125, not at 3.
  EXPECT_EQ(run(q("off.png") + " " + q("ref.exr") + " --fail-percent 3.125").code, 0);
  EXPECT_EQ(run(q("off.png") + " " + q("ref.exr") + " --fail-percent 3").code, 1);
  // Hard limit: any pixel over it fails whatever the percentage allows.
  EXPECT_EQ(run(q("off.png") + " " + q("ref.exr") + " --fail-percent 100 --hard-fail-lsb 5").code,
            1);
  EXPECT_EQ(run(q("off.png") + " " + q("ref.exr") + " --fail-percent 100 --hard-fail-lsb inf").code,
            0);
}

TEST_F(CompareCli, NonFiniteTestFails) {
  Image ref = filled(4, 4, 0.5f, 0.5f, 0.5f);
  write_image(path("ref.exr"), ref);
  ref.at(2, 2)[0] = std::numeric_limits<float>::quiet_NaN();
  write_image(path("nan.exr"), ref);
  const CliResult r = run(q("nan.exr") + " " + q("ref.exr") + " --fail-lsb 255 --fail-percent 100");
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("non-finite"), std::string::npos) << r.err;
}

TEST_F(CompareCli, SizeMismatchIsBadInput) {
  write_image(path("small.png"), filled(4, 4, 0, 0, 0));
  write_image(path("big.exr"), filled(8, 4, 0, 0, 0));
  const CliResult r = run(q("small.png") + " " + q("big.exr") + " --heatmap " + q("heat.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("4x4"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("8x4"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  EXPECT_FALSE(fs::exists(path("heat.png")));  // never written on bad input
}

TEST_F(CompareCli, MissingOrUnreadableFileIsBadInput) {
  write_image(path("ref.exr"), filled(4, 4, 0, 0, 0));
  std::ofstream(path("junk.png")) << "not an image\n";
  for (const std::string& args :
       {q("missing.png") + " " + q("ref.exr"), q("ref.exr") + " " + q("missing.exr"),
        q("junk.png") + " " + q("ref.exr")}) {
    const CliResult r = run(args);
    EXPECT_EQ(r.code, 2) << args;
    EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
    EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u) << r.err;
  }
}

// 68 bytes of valid PNG whose header claims 40000 x 40000 RGB pixels (13.7 GB as float RGB).
const unsigned char kHugeHeaderPng[] = {
    0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0x00, 0x00, 0x00, 0x0d, 0x49, 0x48,
    0x44, 0x52, 0x00, 0x00, 0x9c, 0x40, 0x00, 0x00, 0x9c, 0x40, 0x08, 0x02, 0x00, 0x00,
    0x00, 0xde, 0x6e, 0x99, 0x52, 0x00, 0x00, 0x00, 0x0b, 0x49, 0x44, 0x41, 0x54, 0x78,
    0x9c, 0x63, 0x60, 0x60, 0x00, 0x00, 0x00, 0x03, 0x00, 0x01, 0xb8, 0xad, 0x3a, 0x63,
    0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82};

TEST_F(CompareCli, HeaderSizeIsCheckedBeforeAllocating) {
  write_image(path("ref.exr"), filled(4, 4, 0, 0, 0));
  std::ofstream(path("huge.png"), std::ios::binary)
      .write(reinterpret_cast<const char*>(kHugeHeaderPng), sizeof kHugeHeaderPng);
  // 4 GB of address space: allocating first fails (std::bad_alloc) instead of using 13.7 GB.
  const test::RunResult r = test::run_ltrender("compare " + q("huge.png") + " " + q("ref.exr"),
                                               test::RunLimits{60, 4096});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err, "ltrender: error: " + path("huge.png") +
                       ": header claims 40000x40000 pixels, over the limit of 16777216 (4096^2) "
                       "pixels\n");
}

// libpng's words (the chunk it was reading) are kept in the one line.
TEST_F(CompareCli, TruncatedPngIsOneLine) {
  Image noise(64, 64);
  for (size_t i = 0; i < noise.rgba.size(); ++i)
    noise.rgba[i] = static_cast<float>(i * 7919 % 255) / 255.0f;
  write_image(path("ref.exr"), noise);
  write_image(path("full.png"), noise);
  const std::string png = read_all(path("full.png"));
  std::ofstream(path("cut.png"), std::ios::binary) << png.substr(0, png.size() / 2);
  const CliResult r = run(q("cut.png") + " " + q("ref.exr"));
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ltrender: error: " + path("cut.png") + ": cannot decode image: ", 0), 0u)
      << r.err;
  EXPECT_NE(r.err.find("IDAT"), std::string::npos) << r.err;  // libpng's words are kept
}

TEST_F(CompareCli, BadOptionValuesAreBadInput) {
  write_scene();
  const std::string files = q("same.png") + " " + q("ref.exr");
  for (const std::string& opt : std::vector<std::string>{
           "--fail-lsb -1", "--fail-lsb abc", "--fail-lsb inf", "--fail-percent -0.5",
           "--fail-percent 101", "--hard-fail-lsb -3", "--hard-fail-lsb nan", "--heatmap-max-lsb 0",
           "--region outside", "--heatmap " + q("heat.exr")}) {
    const CliResult r = run(files + " " + opt);
    EXPECT_EQ(r.code, 2) << opt;
    EXPECT_EQ(test::count_lines(r.err), 1) << opt << ": " << r.err;
    EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u) << opt << ": " << r.err;
  }
  const CliResult r = run(files + " --fail-lsb -1");
  EXPECT_NE(r.err.find("--fail-lsb"), std::string::npos) << r.err;
}

TEST_F(CompareCli, HeatmapIsWrittenOnPassAndFail) {
  write_scene();
  CliResult r = run(q("same.png") + " " + q("ref.exr") + " --heatmap " + q("pass.png"));
  EXPECT_EQ(r.code, 0) << r.err;
  r = run(q("off.png") + " " + q("ref.exr") + " --heatmap " + q("fail.png") +
          " --heatmap-max-lsb 10");
  EXPECT_EQ(r.code, 1) << r.err;

  const Image pass = read_image(path("pass.png"));
  ASSERT_EQ(pass.width, 8);
  ASSERT_EQ(pass.height, 8);
  // Covered (0, 0): G is 0.37 -> byte 94, 0.35 LSB off; on 0..8 that is 0.35 / 1.6 of the way
  // from black to blue.
  EXPECT_EQ(pass.at(0, 0)[0], 0.0f);
  EXPECT_EQ(pass.at(0, 0)[1], 0.0f);
  EXPECT_NEAR(pass.at(0, 0)[2], 0.35f / 1.6f, 1.0f / 255.0f);
  EXPECT_NEAR(pass.at(6, 0)[0], kHeatmapUncovered[0], 1.0f / 255.0f);  // uncovered: grey

  const Image fail = read_image(path("fail.png"));
  // ~10 LSB on a 0..10 scale: white, or very near it.
  EXPECT_GT(fail.at(1, 1)[0], 0.9f);
  EXPECT_GT(fail.at(1, 1)[1], 0.8f);
  EXPECT_GT(fail.at(1, 1)[2], 0.8f);
  // No temporary left behind.
  for (const auto& entry : fs::directory_iterator(dir_)) {
    EXPECT_EQ(entry.path().filename().string().find(kPartialOutputTag), std::string::npos)
        << entry.path();
  }
}

TEST_F(CompareCli, HeatmapNeverOverwritesAnInput) {
  write_scene();
  const std::string before = read_all(path("same.png"));
  const CliResult r = run(q("same.png") + " " + q("ref.exr") + " --heatmap " + q("same.png"));
  EXPECT_EQ(r.code, 2);
  EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u) << r.err;
  EXPECT_EQ(read_all(path("same.png")), before);
}

}  // namespace
}  // namespace lt
