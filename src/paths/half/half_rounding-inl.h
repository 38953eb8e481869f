// Rounding a vector of floats to the nearest IEEE binary16 value (ties to even), kept as float:
// the one rounding every operation of the half path ends with (half_shading.h), per Highway
// target. Included once per target by a file compiled through hwy/foreach_target.h, so it has
// Highway's per-target include guard instead of #pragma once.
//
// - With F16C (Highway's AVX2 and AVX-512 targets require it): VCVTPS2PH, which Highway
//   calls with imm8 = _MM_FROUND_NO_EXC = 8: bit 2 clear selects the rounding of bits 1:0, and
//   00 is round to nearest even whatever MXCSR says (Intel SDM vol. 2C, VCVTPS2PH, table
//   "Immediate Byte Encoding for 16-bit Floating-Point Conversion Instructions"); then
//   VCVTPH2PS back, which is exact.
// - Without (SSSE3, SSE4, the emulated targets): Highway 1.0.3's DemoteTo to float16 truncates
//   the mantissa and never makes Inf (hwy/ops/x86_128-inl.h, its HWY_TARGET >= HWY_SSE4
//   branch), so it is not the IEEE rounding; this file rounds in float arithmetic instead.
//   A float of binade 2^e added to 2^(e' + 13), e' = max(e, -14), lands where float's spacing
//   is 2^(e' - 10), half's spacing at 2^e (subnormals: 2^-24): float's own round-to-nearest-even
//   addition rounds it there, and subtracting 2^(e' + 13) again is exact (Sterbenz). |x| >=
//   65520 (halfway between 65504, the largest half, and 2^16) rounds to Inf, NaN stays NaN.
// Both are checked bit for bit against Imath's software rounding on every target this machine
// runs (tests/half_rounding_test.cpp).
#if defined(LT_PATHS_HALF_HALF_ROUNDING_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LT_PATHS_HALF_HALF_ROUNDING_INL_H_
#undef LT_PATHS_HALF_HALF_ROUNDING_INL_H_
#else
#define LT_PATHS_HALF_HALF_ROUNDING_INL_H_
#endif

#include <hwy/highway.h>

#include <limits>

HWY_BEFORE_NAMESPACE();
namespace lt::fp16::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

#if HWY_ARCH_X86 && HWY_TARGET <= HWY_AVX2 && !defined(HWY_DISABLE_F16C)
inline constexpr bool kRoundsWithF16c = true;
#else
inline constexpr bool kRoundsWithF16c = false;
#endif

// x rounded to the nearest binary16 value, ties to even, as a float (exact: every half is a
// float). Overflow gives +-Inf and NaN stays NaN (its payload is not kept).
template <class D>
HWY_INLINE hn::Vec<D> RoundToHalf(D d, hn::Vec<D> x) {
  if constexpr (kRoundsWithF16c) {
    const hn::Rebind<hwy::float16_t, D> df16;
    return hn::PromoteTo(d, hn::DemoteTo(df16, x));
  } else {
    const hn::RebindToSigned<D> di;
    const auto magnitude = hn::Abs(x);
    // 2^e' + 13 as float bits: the binade's exponent field, at least half's smallest normal's.
    const auto exponent = hn::Max(hn::And(hn::BitCast(di, magnitude), hn::Set(di, 0x7F800000)),
                                  hn::Set(di, (127 - 14) << 23));
    const auto shift = hn::BitCast(d, hn::Add(exponent, hn::Set(di, 13 << 23)));
    auto rounded = hn::Sub(hn::Add(magnitude, shift), shift);
    // Beyond 65520 `shift` may itself overflow; those lanes are Inf (or NaN) anyway.
    rounded = hn::IfThenElse(hn::Ge(magnitude, hn::Set(d, 65520.0f)),
                             hn::Set(d, std::numeric_limits<float>::infinity()), rounded);
    return hn::IfThenElse(hn::IsNaN(x), x, hn::CopySignToAbs(rounded, x));
  }
}

}  // namespace lt::fp16::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LT_PATHS_HALF_HALF_ROUNDING_INL_H_
