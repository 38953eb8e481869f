// model::lobe_power (model/lobe_power.h, which says what it computes and why) in double vector
// lanes. Included once per Highway target by a file compiled through hwy/foreach_target.h, so it
// has Highway's per-target include guard instead of #pragma once. The scalar model::lobe_power is
// this with one lane (lobe_power_lanes.cpp), so there is one definition.
#if defined(LT_MODEL_LOBE_POWER_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LT_MODEL_LOBE_POWER_INL_H_
#undef LT_MODEL_LOBE_POWER_INL_H_
#else
#define LT_MODEL_LOBE_POWER_INL_H_
#endif

#include <hwy/highway.h>

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "model/lobe_power.h"

HWY_BEFORE_NAMESPACE();
namespace lt::model::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

template <class D>
struct DoubleDouble {
  hn::Vec<D> hi, lo;  // value hi + lo, |lo| <= ULP(hi) / 2
};

// a * b exactly as hi + lo [Dekker 1971, Mul12]: Veltkamp's split into 26-bit halves, whose
// products are exact; no fused multiply-add (not every target has one, and -ffp-contract=off
// keeps the compiler from forming one), so every target computes the same bits.
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

// (a.hi + a.lo) * (b.hi + b.lo), renormalised (Fast2Sum: |p| >= |e|). The dropped a.lo * b.lo
// and the roundings of the cross terms and of their sum are each below 2^-105 of the product:
// relative error under 2^-103 a product.
template <class D>
HWY_INLINE DoubleDouble<D> Multiply(D d, const DoubleDouble<D>& a, const DoubleDouble<D>& b) {
  const DoubleDouble<D> p = TwoProduct(d, a.hi, b.hi);
  const auto e = hn::Add(p.lo, hn::Add(hn::Mul(a.hi, b.lo), hn::Mul(a.lo, b.hi)));
  const auto hi = hn::Add(p.hi, e);
  return {hi, hn::Sub(e, hn::Sub(hi, p.hi))};
}

// x^p for a whole p in 1..64, rounded to the nearest double. Binary powering: x^(2^k) by k
// squarings, each doubling the relative error it is given and adding one product's, so
// (2^k - 1) products' worth; the products of the x^(2^k) that p's bits pick add one each. In all
// at most p - 1 products' worth: 63 * 2^-103 < 2^-97 for p <= 64, which is below 2^-44 ULP of
// x^p.
template <class D>
HWY_INLINE hn::Vec<D> WholePower(D d, hn::Vec<D> x, int p) {
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
  // Multiply's Fast2Sum leaves hi the nearest double to hi + lo; a lone x (p = 1) is x.
  return result.hi;
}

// model::lobe_power(x, p) in the lanes of `wanted`: the whole power where it applies (x in
// (0, 1], x^p >= 2^-800: every partial product and its error term stay normal numbers), the rest
// one lane at a time through std::pow; lanes outside `wanted` hold anything and cost nothing.
// `std_pow_calls` counts the std::pow calls.
template <class D>
HWY_INLINE hn::Vec<D> LobePower(D d, hn::Vec<D> x, double p, hn::Mask<D> wanted,
                                size_t* std_pow_calls = nullptr) {
  constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
  const hn::RebindToUnsigned<D> du;
  hn::Vec<D> fast = hn::Zero(d);
  // A light behind every pixel of the vector (t <= 0 for all) costs nothing.
  if (hn::AllFalse(d, wanted)) return fast;
  hn::Mask<D> whole = hn::FirstN(d, 0);
  if (is_whole_power(p)) {
    fast = WholePower(d, x, static_cast<int>(p));
    // NaN x fails the comparisons.
    whole = hn::And(hn::Ge(fast, hn::Set(d, 0x1p-800)),
                    hn::And(hn::Gt(x, hn::Zero(d)), hn::Le(x, hn::Set(d, 1.0))));
  }
  const auto left = hn::AndNot(whole, wanted);
  if (hn::AllFalse(d, left)) return fast;
  alignas(HWY_MAX_BYTES) double xs[kMaxLanes], out[kMaxLanes];
  alignas(HWY_MAX_BYTES) std::uint64_t call[kMaxLanes];
  hn::Store(x, d, xs);
  hn::Store(fast, d, out);
  hn::Store(hn::BitCast(du, hn::VecFromMask(d, left)), du, call);
  for (size_t i = 0; i < hn::Lanes(d); ++i) {
    if (call[i] == 0) continue;
    out[i] = std::pow(xs[i], p);
    if (std_pow_calls) ++*std_pow_calls;
  }
  return hn::Load(d, out);
}

}  // namespace lt::model::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LT_MODEL_LOBE_POWER_INL_H_
