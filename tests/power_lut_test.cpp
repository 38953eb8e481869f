// The power LUT (src/model/power_lut.h): texel values built in double, quantisation per format,
// texel-centre addressing, and the interpolation error bound against t^p.
#include "model/power_lut.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lt::model {
namespace {

TEST(PowerLut, TexelsAreTPowerPAtTexelPositions) {
  const PowerLut lut = PowerLut::build(5, LutFormat::F32, {2.0});
  ASSERT_EQ(lut.rows(), 1);
  // t_i = i / (N - 1): 0, 0.25, 0.5, 0.75, 1.
  EXPECT_FLOAT_EQ(lut.texel(0, 0), 0.0f);
  EXPECT_FLOAT_EQ(lut.texel(0, 1), 0.0625f);
  EXPECT_FLOAT_EQ(lut.texel(0, 2), 0.25f);
  EXPECT_FLOAT_EQ(lut.texel(0, 3), 0.5625f);
  EXPECT_FLOAT_EQ(lut.texel(0, 4), 1.0f);
}

TEST(PowerLut, ZeroPowerIsOneEverywhereIncludingZero) {
  const PowerLut lut = PowerLut::build(4, LutFormat::U8, {0.0});
  for (int i = 0; i < 4; ++i) EXPECT_EQ(lut.texel(0, i), 1.0f) << i;  // 0^0 := 1
}

TEST(PowerLut, U8RoundsToNearestOf255Steps) {
  const PowerLut lut = PowerLut::build(256, LutFormat::U8, {3.0});
  for (int i = 0; i < 256; ++i) {
    const double exact = std::pow(i / 255.0, 3.0);
    const double stored = lut.texel(0, i);
    EXPECT_NEAR(stored * 255, std::round(stored * 255), 1e-4) << "not a multiple of 1/255";
    EXPECT_LE(std::abs(stored - exact), 0.5 / 255 + 1e-7) << i;
  }
  // 0.5^3 = 0.125 -> 31.875 -> 32.
  const PowerLut three = PowerLut::build(3, LutFormat::U8, {3.0});
  EXPECT_FLOAT_EQ(three.texel(0, 1), 32.0f / 255.0f);
}

TEST(PowerLut, F16RoundsToNearestHalfAndKeepsDenormals) {
  const PowerLut lut = PowerLut::build(3, LutFormat::F16, {1.0});
  EXPECT_EQ(lut.texel(0, 1), 0.5f);  // exact
  const PowerLut cube = PowerLut::build(3, LutFormat::F16, {20.0});
  // 0.5^20 = 2^-20 is a half denormal (below 2^-14): kept exactly, not flushed.
  EXPECT_EQ(cube.texel(0, 1), std::ldexp(1.0f, -20));
  const PowerLut third = PowerLut::build(4, LutFormat::F16, {1.0});
  EXPECT_EQ(third.texel(0, 1), 0.333251953125f);  // 1/3 as a half: 0x3555
}

TEST(PowerLut, TexelCentreAddressingHitsTexelsExactly) {
  const PowerLut lut = PowerLut::build(16, LutFormat::F32, {5.0});
  for (int i = 0; i < 16; ++i) {
    const double t = i / 15.0;
    // GL samples texel i's centre at u = (i + 0.5) / N.
    EXPECT_NEAR(lut.coordinate(t), (i + 0.5) / 16, 1e-15);
    EXPECT_NEAR(lut.sample_linear(0, t), lut.texel(0, i), 1e-12) << i;
  }
  // Outside [0, 1] clamp-to-edge returns the end texels.
  EXPECT_DOUBLE_EQ(lut.sample_linear(0, -1), lut.texel(0, 0));
  EXPECT_DOUBLE_EQ(lut.sample_linear(0, 2), lut.texel(0, 15));
}

TEST(PowerLut, LinearInterpolationErrorBound) {
  // Linear interpolation of f = t^p between texels h = 1/(N-1) apart errs by at most
  // h^2/8 * max|f''| = h^2/8 * p(p-1) on [0, 1] (p >= 2), plus the f32 rounding of the texels.
  for (double p : {2.0, 4.0, 8.0}) {
    for (int n : {16, 64, 256}) {
      const PowerLut lut = PowerLut::build(n, LutFormat::F32, {p});
      const double h = 1.0 / (n - 1);
      const double bound = h * h / 8 * p * (p - 1) + 1e-7;
      double worst = 0;
      for (int i = 0; i <= 10000; ++i) {
        const double t = i / 10000.0;
        worst = std::max(worst, std::abs(lut.sample_linear(0, t) - std::pow(t, p)));
      }
      EXPECT_LE(worst, bound) << "p " << p << " N " << n;
      EXPECT_GT(worst, bound / 20) << "the bound should be roughly tight";
    }
  }
}

}  // namespace
}  // namespace lt::model
