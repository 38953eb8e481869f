// to_unorm8 is the one 8-bit rounding of images, LUT texels, cube maps and GXColor components:
// clamp to [0, 1], round to nearest, so every byte is within 0.5 LSB of the clamped value and a
// stored k / 255 comes back as k. Expectations are computed here independently (exact integer
// reasoning on k / 255 and the distance bound), not copied from the implementation.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>

#include "image/image.h"

namespace lt {
namespace {

TEST(Unorm8, EveryStoredByteComesBackExactly) {
  for (int k = 0; k <= 255; ++k) {
    EXPECT_EQ(to_unorm8(k / 255.0), k) << k;
    EXPECT_EQ(to_unorm8(static_cast<float>(k) / 255.0f), k) << k;
  }
}

TEST(Unorm8, EveryByteIsWithinHalfAnLsbOfTheClampedValue) {
  // A dense sweep over [-0.1, 1.1] in double, then values just either side of the midpoints
  // (k + 0.5) / 255, where a wrong rounding direction (truncation, or rounding half down) shows.
  for (int i = -1000; i <= 11000; ++i) {
    const double v = i / 10000.0;
    const double clamped = std::fmin(1.0, std::fmax(0.0, v));
    EXPECT_LE(std::fabs(to_unorm8(v) - clamped * 255.0), 0.5) << v;
  }
  for (int k = 0; k < 255; ++k) {
    const double mid = (k + 0.5) / 255.0;
    EXPECT_EQ(to_unorm8(mid - 1e-9), k) << k;
    EXPECT_EQ(to_unorm8(mid + 1e-9), k + 1) << k;
  }
}

TEST(Unorm8, FloatAndDoubleAgreeOnEveryFloatTheyShare) {
  // The float overload must not round its product in float: 0.7f * 255 is 178.5 in float and
  // would land on 179, 0.500003 LSB from 0.7f.
  EXPECT_EQ(to_unorm8(0.7f), 178);
  for (int i = 0; i <= 100000; ++i) {
    const float f = static_cast<float>(i) / 100000.0f;
    ASSERT_EQ(to_unorm8(f), to_unorm8(static_cast<double>(f))) << f;
  }
}

TEST(Unorm8, OutOfRangeAndNonFiniteClamp) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(to_unorm8(std::nan("")), 0);  // a NaN never reaches a byte as garbage
  EXPECT_EQ(to_unorm8(std::nanf("")), 0);
  EXPECT_EQ(to_unorm8(-inf), 0);
  EXPECT_EQ(to_unorm8(inf), 255);
  EXPECT_EQ(to_unorm8(-1e-300), 0);
  EXPECT_EQ(to_unorm8(1.0 + 1e-12), 255);
  EXPECT_EQ(to_unorm8(42.0), 255);
}

}  // namespace
}  // namespace lt
