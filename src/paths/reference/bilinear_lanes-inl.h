// model::sample_bilinear (model/texture_sampling.h, the definition) in double vector lanes, a
// pixel's (u, v) a lane: the taps' positions, weights and wrapped indices in the lanes with the
// scalar's operations in its order (the wrap's modulo exact in double), the texel loads a lane
// at a time, the filter in the lanes in its order, so every lane is model::sample_bilinear's
// value to the bit.
// Included once per Highway target by a file compiled through hwy/foreach_target.h, so it has
// Highway's per-target include guard instead of #pragma once. tests/reference_lanes_test.cpp
// holds it to model::sample_bilinear on every target.
#if defined(LT_PATHS_REFERENCE_BILINEAR_LANES_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef LT_PATHS_REFERENCE_BILINEAR_LANES_INL_H_
#undef LT_PATHS_REFERENCE_BILINEAR_LANES_INL_H_
#else
#define LT_PATHS_REFERENCE_BILINEAR_LANES_INL_H_
#endif

#include <hwy/highway.h>

#include <cstddef>

#include "model/texture_sampling.h"

HWY_BEFORE_NAMESPACE();
namespace lt::reference::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

// One axis's taps of every lane (model's axis_taps): the lower and upper texel and the upper's
// weight.
template <class D>
struct AxisTapsLanes {
  hn::Vec<D> i0, i1, f;
};

// model's wrap_index: i modulo the period (size, or 2 size mirrored) into [0, period), mirrored
// back into [0, size). Exact in double: i is a whole number of at most 1e15 + 1 (axis_taps clamps
// beyond), so where i / period is not whole it lies at least 1 / period from the next whole
// number, while its rounding moves it at most 1e15 * 2^-53 / period = 0.11 / period; the floor of
// the rounded quotient is the true one, and i - q * period is exact (both below 2^53).
template <class D>
HWY_INLINE hn::Vec<D> WrapIndex(D d, hn::Vec<D> i, int size, model::Wrap wrap) {
  const double period = wrap == model::Wrap::Repeat ? size : 2.0 * size;
  const auto p = hn::Set(d, period);
  const auto m = hn::Sub(i, hn::Mul(hn::Floor(hn::Div(i, p)), p));
  return hn::IfThenElse(hn::Lt(m, hn::Set(d, static_cast<double>(size))), m,
                        hn::Sub(hn::Set(d, period - 1), m));
}

template <class D>
HWY_INLINE AxisTapsLanes<D> AxisTaps(D d, hn::Vec<D> coordinate, int size, model::Wrap wrap) {
  const auto last = hn::Set(d, static_cast<double>(size - 1));
  const auto x =
      hn::Sub(hn::Mul(coordinate, hn::Set(d, static_cast<double>(size))), hn::Set(d, 0.5));
  // CLAMP_TO_EDGE, NaN, Inf and |x| > 1e15: `if (!(x > 0)) x = 0; x = std::min(x, size - 1)`,
  // i0 = floor(x), i1 = std::min(i0 + 1, size - 1), f = x - i0.
  auto xc = hn::IfThenElse(hn::Gt(x, hn::Zero(d)), x, hn::Zero(d));
  xc = hn::IfThenElse(hn::Lt(last, xc), last, xc);
  const auto i0c = hn::Floor(xc);
  const auto i1c = hn::Min(hn::Add(i0c, hn::Set(d, 1.0)), last);
  const auto fc = hn::Sub(xc, i0c);
  if (wrap == model::Wrap::ClampToEdge) return {i0c, i1c, fc};
  const auto clamped = hn::Or(hn::Not(hn::IsFinite(x)), hn::Gt(hn::Abs(x), hn::Set(d, 1e15)));
  // REPEAT and MIRRORED_REPEAT: lower = floor(x), f = x - lower, each index wrapped.
  const auto lower = hn::Floor(x);
  const auto i0 = WrapIndex(d, lower, size, wrap);
  const auto i1 = WrapIndex(d, hn::Add(lower, hn::Set(d, 1.0)), size, wrap);
  return {hn::IfThenElse(clamped, i0c, i0), hn::IfThenElse(clamped, i1c, i1),
          hn::IfThenElse(clamped, fc, hn::Sub(x, lower))};
}

// model::sample_bilinear(texture, (u[i], v[i])) for every lane i.
template <class D>
HWY_INLINE void SampleBilinear(D d, const model::Texture& texture, hn::Vec<D> u, hn::Vec<D> v,
                               hn::Vec<D> (&rgb)[3]) {
  constexpr size_t kMaxLanes = HWY_MAX_BYTES / sizeof(double);
  const AxisTapsLanes<D> tx = AxisTaps(d, u, texture.width, texture.wrap_s);
  const AxisTapsLanes<D> ty = AxisTaps(d, v, texture.height, texture.wrap_t);
  alignas(HWY_MAX_BYTES) double x0[kMaxLanes], x1[kMaxLanes], y0[kMaxLanes], y1[kMaxLanes];
  alignas(HWY_MAX_BYTES) double fx[kMaxLanes], fy[kMaxLanes];
  hn::Store(tx.i0, d, x0);
  hn::Store(tx.i1, d, x1);
  hn::Store(ty.i0, d, y0);
  hn::Store(ty.i1, d, y1);
  hn::Store(tx.f, d, fx);
  hn::Store(ty.f, d, fy);
  const size_t n = hn::Lanes(d);
  // The four texels of each lane, channel by channel (float texels widened, as texel() does).
  alignas(HWY_MAX_BYTES) double t00[3][kMaxLanes], t10[3][kMaxLanes], t01[3][kMaxLanes],
      t11[3][kMaxLanes];
  const size_t w = static_cast<size_t>(texture.width);
  const float* const texels = texture.texels.data();
  for (size_t i = 0; i < n; ++i) {
    const auto at = [&](double x, double y) {
      return texels + (static_cast<size_t>(y) * w + static_cast<size_t>(x)) * 3;
    };
    const float *p00 = at(x0[i], y0[i]), *p10 = at(x1[i], y0[i]);
    const float *p01 = at(x0[i], y1[i]), *p11 = at(x1[i], y1[i]);
    for (int c = 0; c < 3; ++c) {
      t00[c][i] = p00[c], t10[c][i] = p10[c], t01[c][i] = p01[c], t11[c][i] = p11[c];
    }
  }
  // (1 - fy) ((1 - fx) t00 + fx t10) + fy ((1 - fx) t01 + fx t11), glm's order.
  const auto one = hn::Set(d, 1.0);
  const auto wx = hn::Load(d, fx), wy = hn::Load(d, fy);
  const auto ux = hn::Sub(one, wx), uy = hn::Sub(one, wy);
  for (int c = 0; c < 3; ++c) {
    const auto bottom = hn::Add(hn::Mul(ux, hn::Load(d, t00[c])), hn::Mul(wx, hn::Load(d, t10[c])));
    const auto top = hn::Add(hn::Mul(ux, hn::Load(d, t01[c])), hn::Mul(wx, hn::Load(d, t11[c])));
    rgb[c] = hn::Add(hn::Mul(uy, bottom), hn::Mul(wy, top));
  }
}

}  // namespace lt::reference::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LT_PATHS_REFERENCE_BILINEAR_LANES_INL_H_
