// model::sample_bilinear (model/texture_sampling.h, the definition) in double vector lanes, a
// pixel's (u, v) a lane: the taps' positions, weights and wrapped indices in the lanes with the
// scalar's operations in its order (the wrap's modulo exact in double), the texels gathered, the
// filter in the lanes in its order, so every lane is model::sample_bilinear's value to the bit.
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
#include <cstdint>

#include "core/error.h"
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

// model::sample_bilinear(texture, (u[i], v[i])) for every lane i. The four texels of a lane are
// gathered channel by channel (float texels widened, as texel() does) at the first float of each,
// (y * width + x) * 3: whole numbers below 2^31, so exact in double and in int32 lanes (a map is
// at most kMaxImagePixels = 4096^2 texels, 50 M floats; the check guards a texture made in code).
template <class D>
HWY_INLINE void SampleBilinear(D d, const model::Texture& texture, hn::Vec<D> u, hn::Vec<D> v,
                               hn::Vec<D> (&rgb)[3]) {
  LT_CHECK(texture.texels.size() <= 0x7fffffffu, "a texture's floats are indexed in int32 lanes");
  const AxisTapsLanes<D> tx = AxisTaps(d, u, texture.width, texture.wrap_s);
  const AxisTapsLanes<D> ty = AxisTaps(d, v, texture.height, texture.wrap_t);
  const hn::Rebind<float, D> df;
  const hn::Rebind<int32_t, D> di;
  const auto width = hn::Set(d, static_cast<double>(texture.width));
  const auto three = hn::Set(d, 3.0);
  const auto first_float = [&](hn::Vec<D> x, hn::Vec<D> y) {
    return hn::DemoteTo(di, hn::Mul(hn::Add(hn::Mul(y, width), x), three));
  };
  const auto i00 = first_float(tx.i0, ty.i0), i10 = first_float(tx.i1, ty.i0);
  const auto i01 = first_float(tx.i0, ty.i1), i11 = first_float(tx.i1, ty.i1);
  const float* const texels = texture.texels.data();
  const auto texel = [&](int c, hn::Vec<decltype(di)> i) {
    return hn::PromoteTo(d, hn::GatherIndex(df, texels + c, i));
  };
  // (1 - fy) ((1 - fx) t00 + fx t10) + fy ((1 - fx) t01 + fx t11), glm's order.
  const auto one = hn::Set(d, 1.0);
  const auto ux = hn::Sub(one, tx.f), uy = hn::Sub(one, ty.f);
  for (int c = 0; c < 3; ++c) {
    const auto bottom = hn::Add(hn::Mul(ux, texel(c, i00)), hn::Mul(tx.f, texel(c, i10)));
    const auto top = hn::Add(hn::Mul(ux, texel(c, i01)), hn::Mul(tx.f, texel(c, i11)));
    rgb[c] = hn::Add(hn::Mul(uy, bottom), hn::Mul(ty.f, top));
  }
}

}  // namespace lt::reference::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif  // LT_PATHS_REFERENCE_BILINEAR_LANES_INL_H_
