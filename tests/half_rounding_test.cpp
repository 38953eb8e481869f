// The half path's rounding in vector lanes (paths/half/half_rounding-inl.h: F16C's VCVTPS2PH on
// AVX2 and AVX-512, float arithmetic elsewhere) against Imath's software rounding, which the
// path used before it was vectorised (issue 39): bit for bit, on every Highway target this
// machine runs, over every binary16 value, every halfway point between two of them (and the
// floats either side), and a seeded million products, sums, differences and quotients.
#include <Imath/half.h>
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/simd_target.h"
#include "paths/half/half_shading_lanes.h"

namespace lt {
namespace {

// Imath's rounding, the expectation: float -> half (round to nearest even) -> float.
float imath_round(float x) {
  return float(Imath::half(x));
}

float half_from_bits(std::uint16_t bits) {
  Imath::half h;
  h.setBits(bits);
  return float(h);
}

// Every float of `in` through fp16::round_to_half on `target`, against Imath, bit for bit (a
// NaN need only stay a NaN: neither keeps the payload the other does). Returns the mismatches.
size_t mismatches_on(std::int64_t target, const std::vector<float>& in) {
  hwy::SetSupportedTargetsForTest(target);
  std::vector<float> out(in.size());
  fp16::round_to_half(in.data(), out.data(), in.size());
  size_t bad = 0;
  for (size_t i = 0; i < in.size(); ++i) {
    const float want = imath_round(in[i]);
    const bool same = std::isnan(want) ? std::isnan(out[i])
                                       : std::bit_cast<std::uint32_t>(out[i]) ==
                                             std::bit_cast<std::uint32_t>(want);
    if (!same && bad++ < 5) {
      ADD_FAILURE() << hwy::TargetName(target) << ": " << in[i] << " (0x" << std::hex
                    << std::bit_cast<std::uint32_t>(in[i]) << ") -> 0x"
                    << std::bit_cast<std::uint32_t>(out[i]) << ", Imath 0x"
                    << std::bit_cast<std::uint32_t>(want) << std::dec;
    }
  }
  hwy::SetSupportedTargetsForTest(0);
  return bad;
}

// Every half, and around every halfway point between neighbours: the tie itself (which rounds
// to the even one) and the floats one ulp either side of it (which must not).
std::vector<float> every_half_and_every_tie() {
  std::vector<float> v;
  for (std::uint32_t bits = 0; bits < 0x10000; ++bits) {
    const float h = half_from_bits(static_cast<std::uint16_t>(bits));
    v.push_back(h);
    if (std::isnan(h) || std::isinf(h)) continue;
    // The next half away from zero; past 65504 the "next" is 65536, where Inf begins.
    const bool top = (bits & 0x7FFF) == 0x7BFF;
    const float next =
        top ? std::copysign(65536.0f, h) : half_from_bits(static_cast<std::uint16_t>(bits + 1));
    if (std::isnan(next)) continue;
    const float tie = h + (next - h) / 2;  // exact: both are halves, 11 bits apart at most
    v.push_back(tie);
    v.push_back(std::nextafter(tie, 0.0f));
    v.push_back(std::nextafter(tie, std::copysign(INFINITY, tie)));
  }
  return v;
}

// What the shading rounds: the float result of one operation on two halves.
std::vector<float> seeded_operations(size_t pairs) {
  std::mt19937 rng(39);  // the number: any fixed seed
  std::uniform_int_distribution<std::uint32_t> bits(0, 0xFFFF);
  std::vector<float> v;
  v.reserve(pairs * 5);
  for (size_t i = 0; i < pairs; ++i) {
    const float a = half_from_bits(static_cast<std::uint16_t>(bits(rng)));
    const float b = half_from_bits(static_cast<std::uint16_t>(bits(rng)));
    v.push_back(a * b);
    v.push_back(a + b);
    v.push_back(a - b);
    v.push_back(a / b);
    v.push_back(std::sqrt(std::fabs(a)));
  }
  return v;
}

TEST(HalfRounding, EveryTargetRoundsEveryHalfAndEveryTieAsImath) {
  const std::vector<float> in = every_half_and_every_tie();
  ASSERT_GT(in.size(), 4u * 60000);
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (std::int64_t t : targets) EXPECT_EQ(mismatches_on(t, in), 0u) << hwy::TargetName(t);
}

TEST(HalfRounding, EveryTargetRoundsSeededProductsAndSumsAsImath) {
  const std::vector<float> in = seeded_operations(1'000'000);
  for (std::int64_t t : hwy::SupportedAndGeneratedTargets())
    EXPECT_EQ(mismatches_on(t, in), 0u) << hwy::TargetName(t);
}

// The dispatch follows the target the test sets, so the loops above reach every target's code
// (F16C and the float-arithmetic rounding alike) and not the best one five times: every
// HWY_DYNAMIC_DISPATCH table (simd_target's among them) chooses from the targets set.
TEST(HalfRounding, DispatchRunsTheTargetSet) {
  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  for (std::int64_t t : targets) {
    hwy::SetSupportedTargetsForTest(t);
    EXPECT_EQ(simd_target(), hwy::TargetName(t));
  }
  hwy::SetSupportedTargetsForTest(0);
  // Both kinds of rounding are among them on any x86-64 machine with AVX2.
  if (hwy::SupportedTargets() & HWY_AVX2) {
    EXPECT_GE(targets.size(), 2u) << "no target without F16C compiled";
  }
}

}  // namespace
}  // namespace lt
