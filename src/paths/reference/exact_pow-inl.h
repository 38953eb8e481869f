// std::pow(x, p) in double vector lanes for a whole exponent p (the demo scenes' translucency
// powers are 3 to 8), equal to std::pow to the bit: most lanes without calling it, the rest
// through it. Included once per Highway target by a file compiled through hwy/foreach_target.h,
// so it has Highway's per-target include guard instead of #pragma once.
//
// Why it is std::pow's value. glibc's pow since 2.28 (sysdeps/ieee754/dbl-64/e_pow.c, from Arm's
// optimized-routines; Debian 12 ships 2.36) documents its worst-case error as 0.54 ULP ("~=
// ulperr_exp + 1024*Ln2*relerr_log*2^53"), with or without FMA. So where the exact x^p lies more
// than 0.04 ULP from the midpoint between two doubles, the only double within 0.54 ULP of it is the
// nearest one, and that is what std::pow returns. Here x^p is computed as a double-double (binary
// powering, each product exact by Dekker's split, relative error below 2^-98 for p <= 64), its
// leading double is the nearest double to it, and a lane is kept only where the trailing part
// puts the exact value more than 1/16 ULP from a midpoint (and the result is a normal number far
// from underflow). Every other lane -- about one in eight, and NaN, tiny and non-positive x --
// calls std::pow. tests/reference_lanes_test.cpp holds the lanes to the std::pow the binary
// links (ExactPow.*: 230,000 values x 16 powers, bit for bit) on every target, so a C library
// without that bound fails there rather than moving a pixel unseen.
#if defined(LT_PATHS_REFERENCE_EXACT_POW_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LT_PATHS_REFERENCE_EXACT_POW_INL_H_
#undef LT_PATHS_REFERENCE_EXACT_POW_INL_H_
#else
#define LT_PATHS_REFERENCE_EXACT_POW_INL_H_
#endif

#include <hwy/highway.h>

#include <cmath>
#include <cstdint>

HWY_BEFORE_NAMESPACE();
namespace lt::reference::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// The exponents the lanes take: whole numbers 1..64 (beyond, the double-double's error bound
// above no longer holds as stated).
inline bool lanes_take_power(double p) {
  return p >= 1 && p <= 64 && p == std::floor(p);
}

template <class D>
struct DoubleDouble {
  hn::Vec<D> hi, lo;  // value hi + lo, |lo| <= ULP(hi) / 2
};

// a * b exactly as hi + lo [Dekker 1971, Mul12]: Veltkamp's split into 26-bit halves, whose
// products are exact; no fused multiply-add (not every target has one, and -ffp-contract=off
// keeps the compiler from forming one).
template <class D>
HWY_INLINE DoubleDouble<D> TwoProduct(D d, hn::Vec<D> a, hn::Vec<D> b) {
  const auto splitter = hn::Set(d, 134217729.0);  // 2^27 + 1
  const auto ca = hn::Mul(splitter, a), cb = hn::Mul(splitter, b);
  const auto a_hi = hn::Sub(ca, hn::Sub(ca, a)), b_hi = hn::Sub(cb, hn::Sub(cb, b));
  const auto a_lo = hn::Sub(a, a_hi), b_lo = hn::Sub(b, b_hi);
  const auto p = hn::Mul(a, b);
  const auto e = hn::Add(
      hn::Add(hn::Add(hn::Sub(hn::Mul(a_hi, b_hi), p), hn::Mul(a_hi, b_lo)), hn::Mul(a_lo, b_hi)),
      hn::Mul(a_lo, b_lo));
  return {p, e};
}

// (a.hi + a.lo) * (b.hi + b.lo), renormalised (Fast2Sum: |p| >= |e|): relative error about
// 2^-104 a product.
template <class D>
HWY_INLINE DoubleDouble<D> Multiply(D d, const DoubleDouble<D>& a, const DoubleDouble<D>& b) {
  const DoubleDouble<D> p = TwoProduct(d, a.hi, b.hi);
  const auto e = hn::Add(p.lo, hn::Add(hn::Mul(a.hi, b.lo), hn::Mul(a.lo, b.hi)));
  const auto hi = hn::Add(p.hi, e);
  return {hi, hn::Sub(e, hn::Sub(hi, p.hi))};
}

// x^p for a whole p in 1..64 (lanes_take_power), and in `certain` the lanes whose result is
// std::pow(x, p) to the bit (the file's comment says why); the other lanes hold anything.
template <class D>
HWY_INLINE hn::Vec<D> CertifiedPower(D d, hn::Vec<D> x, int p, hn::Mask<D>& certain) {
  DoubleDouble<D> base{x, hn::Zero(d)};
  DoubleDouble<D> result{hn::Set(d, 1.0), hn::Zero(d)};
  bool first = true;
  for (int e = p; e != 0; e >>= 1) {
    if (e & 1) {
      result = first ? base : Multiply(d, result, base);
      first = false;
    }
    if (e > 1) base = Multiply(d, base, base);
  }
  const hn::RebindToUnsigned<D> du;
  const auto bits = hn::BitCast(du, result.hi);
  // ULP(hi) = 2^(exponent - 52), from hi's exponent field.
  const auto binade = hn::BitCast(d, hn::And(bits, hn::Set(du, 0x7ff0000000000000ull)));
  const auto ulp = hn::Mul(binade, hn::Set(d, 0x1p-52));
  // More than 1/16 ULP from the midpoint: |lo| < (1/2 - 1/16) ULP. At a power of two with lo < 0
  // the next double down is half an ULP away, so such a lane is left to std::pow.
  const auto clear_of_midpoint = hn::Lt(hn::Abs(result.lo), hn::Mul(ulp, hn::Set(d, 0.4375)));
  const auto power_of_two_below = hn::And(
      hn::RebindMask(d, hn::Eq(hn::And(bits, hn::Set(du, 0x000fffffffffffffull)), hn::Zero(du))),
      hn::Lt(result.lo, hn::Zero(d)));
  // Far from underflow (every partial product and its error term stays normal), and x itself
  // in (0, 1] as the lobe's t is (NaN fails the comparison).
  const auto in_range = hn::And(hn::Ge(result.hi, hn::Set(d, 0x1p-800)),
                                hn::And(hn::Gt(x, hn::Zero(d)), hn::Le(x, hn::Set(d, 1.0))));
  certain = hn::AndNot(power_of_two_below, hn::And(clear_of_midpoint, in_range));
  return result.hi;
}

// std::pow(x, p) in the lanes of `wanted`: the certified lanes from CertifiedPower when the lanes
// take p, the others one at a time through std::pow; lanes outside `wanted` hold anything and
// cost nothing. `uncertain_lanes` counts the std::pow calls (tests check the share stays small).
template <class D>
HWY_INLINE hn::Vec<D> ExactPow(D d, hn::Vec<D> x, double p, hn::Mask<D> wanted,
                               size_t* uncertain_lanes = nullptr) {
  constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
  const hn::RebindToUnsigned<D> du;
  hn::Vec<D> fast = hn::Zero(d);
  // A light behind every pixel of the vector (t <= 0 for all) costs nothing, as before.
  if (hn::AllFalse(d, wanted)) return fast;
  hn::Mask<D> certain = hn::FirstN(d, 0);
  if (lanes_take_power(p)) fast = CertifiedPower(d, x, static_cast<int>(p), certain);
  const auto left = hn::AndNot(certain, wanted);
  if (hn::AllFalse(d, left)) return fast;
  alignas(HWY_MAX_BYTES) double xs[kMaxLanes], out[kMaxLanes];
  alignas(HWY_MAX_BYTES) std::uint64_t call[kMaxLanes];
  hn::Store(x, d, xs);
  hn::Store(fast, d, out);
  hn::Store(hn::BitCast(du, hn::VecFromMask(d, left)), du, call);
  for (size_t i = 0; i < hn::Lanes(d); ++i) {
    if (call[i] == 0) continue;
    out[i] = std::pow(xs[i], p);
    if (uncertain_lanes) ++*uncertain_lanes;
  }
  return hn::Load(d, out);
}

}  // namespace lt::reference::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LT_PATHS_REFERENCE_EXACT_POW_INL_H_
