// The lobe's power (model/lobe_power.h) against x^p computed independently in binary128 (GCC's
// __float128, 113-bit significand, libgcc's soft-float): for a whole p up to 64 it must be that
// value correctly rounded to double, on every Highway target this machine runs, and std::pow to
// the bit everywhere else. Binary powering in binary128 rounds at most 12 times, so its x^p is
// within 2^-54 ULP of the exact one; the two could disagree only where x^p lies within 2^-44 ULP
// of a midpoint between doubles and is not one exactly, about one x in 2^43.
#include "model/lobe_power.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <limits>
#include <random>
#include <vector>

#include "model/translucency.h"

namespace lt::model {
namespace {

__extension__ typedef __float128 Quad;  // __extension__: GCC's type, not ISO C++'s

// x^p by binary powering in binary128, rounded once to double.
double quad_power(double x, int p) {
  Quad base = x, result = 1;
  for (int e = p; e != 0; e >>= 1) {
    if (e & 1) result *= base;
    if (e > 1) base *= base;
  }
  return static_cast<double>(result);
}

// The lobe's t: uniform over (0, 1).
std::vector<double> uniform_bases(size_t n) {
  std::mt19937_64 rng(20261206);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<double> xs;
  for (size_t i = 0; i < n; ++i) xs.push_back(unit(rng));
  return xs;
}

// The uniform bases, then the hard ones: random mantissa bits at every exponent (subnormals
// included), the doubles just below 1, every power of two, and values the lobe never passes that
// must still answer as std::pow (0, -0, negatives, above 1, NaN, Inf).
std::vector<double> bases(size_t uniform) {
  std::vector<double> xs = uniform_bases(uniform);
  std::mt19937_64 rng(39);
  for (int i = 0; i < 20000; ++i)
    xs.push_back(std::bit_cast<double>(rng() % 0x3ff0000000000001ull));
  for (int k = 0; k < 2000; ++k) xs.push_back(1.0 - k * 0x1p-53);
  for (int e = 0; e <= 1074; ++e) xs.push_back(std::ldexp(1.0, -e));
  for (double special : {0.0, -0.0, -0.5, 1.5, 2.0, std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::infinity()})
    xs.push_back(special);
  return xs;
}

// What lobe_power.h says lobe_power(x, p) is.
double expected(double x, double p) {
  if (is_whole_power(p) && x > 0 && x <= 1) {
    const double q = quad_power(x, static_cast<int>(p));
    if (q >= 0x1p-800) return q;
  }
  return std::pow(x, p);
}

TEST(LobePower, IsTheCorrectlyRoundedWholePowerAndStdPowElsewhereOnEveryTarget) {
  constexpr size_t kUniform = 200000;
  const std::vector<double> xs = bases(kUniform);
  std::vector<double> got(xs.size());
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_GE(targets.size(), 2u);
  for (double p : {1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 12.0, 16.0, 31.0, 33.0, 63.0, 64.0, 3.5,
                   0.25, 65.0, 1e6}) {
    std::vector<double> want(xs.size());
    for (size_t i = 0; i < xs.size(); ++i) want[i] = expected(xs[i], p);
    for (std::int64_t t : targets) {
      hwy::SetSupportedTargetsForTest(t);
      const size_t calls = lobe_power(xs.data(), p, got.data(), xs.size());
      size_t bad = 0;
      for (size_t i = 0; i < xs.size(); ++i) {
        if (std::bit_cast<std::uint64_t>(got[i]) != std::bit_cast<std::uint64_t>(want[i]) &&
            ++bad <= 3)
          ADD_FAILURE() << hwy::TargetName(t) << " lobe_power(" << std::hexfloat << xs[i] << ", "
                        << std::defaultfloat << p << "): " << std::hexfloat << got[i]
                        << ", expected " << want[i];
      }
      EXPECT_EQ(bad, 0u) << hwy::TargetName(t) << " p = " << p;
      // A whole power calls std::pow only below 2^-800 (uniform t under 2^-12.5 for p = 64).
      const size_t uniform_calls = lobe_power(xs.data(), p, got.data(), kUniform);
      if (is_whole_power(p)) {
        EXPECT_LT(static_cast<double>(uniform_calls) / kUniform, 0.001)
            << hwy::TargetName(t) << " p = " << p;
      } else {
        EXPECT_EQ(calls, xs.size()) << hwy::TargetName(t) << " p = " << p;
      }
    }
  }
  hwy::SetSupportedTargetsForTest(0);
}

// Where the lobe's power and std::pow part, they are neighbouring doubles and std::pow is the one
// farther from x^p: the difference is the C library's rounding, never the lobe's. How often they
// part is printed (glibc 2.36: see docs/performance.md).
TEST(LobePower, PartsFromStdPowOnlyWhereStdPowIsTheFartherNeighbour) {
  const std::vector<double> xs = uniform_bases(200000);
  for (int p = 2; p <= 16; ++p) {
    size_t parted = 0;
    for (double x : xs) {
      const double ours = lobe_power(x, p), libm = std::pow(x, p);
      if (ours == libm) continue;
      ++parted;
      ASSERT_TRUE(libm == std::nextafter(ours, 0.0) || libm == std::nextafter(ours, 1.0))
          << std::hexfloat << x << "^" << p << ": " << ours << ", std::pow " << libm;
      const Quad exact_enough = Quad(x);  // x^p again, kept in binary128
      Quad q = 1;
      for (int i = 0; i < p; ++i) q *= exact_enough;
      const Quad ours_off = q > Quad(ours) ? q - Quad(ours) : Quad(ours) - q;
      const Quad libm_off = q > Quad(libm) ? q - Quad(libm) : Quad(libm) - q;
      EXPECT_TRUE(ours_off < libm_off) << std::hexfloat << x << "^" << p;
    }
    std::cout << "p = " << p << ": std::pow parts from the lobe's power at " << parted << " of "
              << xs.size() << " uniform t\n";
  }
}

// model::lobe's own rules around the power (model.md): 0^0 := 1, t <= 0 -> 0, exact cases exact.
TEST(LobePower, LobeKeepsItsRules) {
  EXPECT_EQ(lobe(0.0, 0.0), 1.0);
  EXPECT_EQ(lobe(0.3, 0.0), 1.0);
  EXPECT_EQ(lobe(0.0, 4.0), 0.0);
  EXPECT_EQ(lobe(-0.25, 4.0), 0.0);
  EXPECT_EQ(lobe(0.5, 4.0), 0.0625);
  EXPECT_EQ(lobe(0.75, 2.0), 0.5625);
  EXPECT_EQ(lobe(1.0, 64.0), 1.0);
  EXPECT_EQ(lobe(0.3, 1.0), 0.3);
  EXPECT_TRUE(std::isnan(lobe(std::numeric_limits<double>::quiet_NaN(), 4.0)));
  EXPECT_EQ(lobe(0.5, 2000.0), 0.0);  // underflow is a plain 0
  EXPECT_EQ(lobe(0.5, 3.5), std::pow(0.5, 3.5));
}

}  // namespace
}  // namespace lt::model
