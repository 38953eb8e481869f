// raster_run.h in float vector lanes. Compiled once per Highway target (hwy/foreach_target.h
// re-includes this file), outside the unity build (CMakeLists.txt). Each function names the
// scalar one of rasteriser.h/.cpp it computes, operation for operation.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gx/raster_run_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cstdint>

#include "gx/raster_run.h"

HWY_BEFORE_NAMESPACE();
namespace lt::gx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using DF = hn::ScalableTag<float>;
using DI = hn::RebindToSigned<DF>;
using VF = hn::Vec<DF>;
using VI = hn::Vec<DI>;

VF kf(float x) {
  return hn::Set(DF(), x);
}
VI ki(s32 x) {
  return hn::Set(DI(), x);
}

// The planes' position terms of the lanes from `lane` on: dx = x_off + (float)(x - x0) and
// dy = y_off + (float)(y - y0) per lane (x - x0 and y - y0 are exact small integers, so their
// conversions are the scalar's).
struct Position {
  VF dx, dy;
};

Position position(const SlopeOrigin& o, const RunPixels& pixels, size_t lane) {
  const DI di;
  const VI x = hn::Sub(hn::Load(di, pixels.x + lane), ki(o.x0));
  const VI y = hn::Sub(hn::Load(di, pixels.y + lane), ki(o.y0));
  return {hn::Add(kf(o.x_off), hn::ConvertTo(DF(), x)),
          hn::Add(kf(o.y_off), hn::ConvertTo(DF(), y))};
}

// slope_value: f0 + (dfdx * dx) + (dfdy * dy), left to right.
VF slope_value(const Slope& s, const Position& p) {
  return hn::Add(hn::Add(kf(s.f0), hn::Mul(kf(s.dfdx), p.dx)), hn::Mul(kf(s.dfdy), p.dy));
}

// x86_float_to_int: truncation, INT_MIN for NaN and anything outside [-2^31, 2^31). The lanes'
// own conversion is used only where the value is in range (Highway saturates the rest).
VI x86_float_to_int(VF v) {
  const auto in_range = hn::And(hn::Ge(v, kf(-2147483648.0f)), hn::Lt(v, kf(2147483648.0f)));
  return hn::IfThenElse(hn::RebindMask(DI(), in_range), hn::ConvertTo(DI(), v), ki(INT32_MIN));
}

// raster_depth: the clamp to 0..16777215 that a NaN passes, then the conversion.
VI raster_depth(VF z) {
  const VF high = hn::IfThenElse(hn::Lt(kf(16777215.0f), z), kf(16777215.0f), z);
  return x86_float_to_int(hn::IfThenElse(hn::Lt(z, kf(0.0f)), kf(0.0f), high));
}

// raster_color: the 16-bit narrowing c, then c & ~(c >> 8), kept to 8 bits.
VI raster_color(VF v) {
  const VI c = hn::And(x86_float_to_int(v), ki(0xffff));
  const VI mask = hn::And(hn::Not(hn::ShiftRight<8>(c)), ki(0xffff));
  return hn::And(hn::And(c, mask), ki(0xff));
}

// rounded_color: NaN as 0, else floor(v + 0.5) clamped to 0..255 as std::clamp compares.
VI rounded_color(VF v) {
  const VF r = hn::Floor(hn::Add(v, kf(0.5f)));
  const VF high = hn::IfThenElse(hn::Lt(kf(255.0f), r), kf(255.0f), r);
  const VF clamped = hn::IfThenElse(hn::Lt(r, kf(0.0f)), kf(0.0f), high);
  const VF no_nan = hn::IfThenElseZero(hn::Eq(v, v), clamped);
  return hn::ConvertTo(DI(), no_nan);
}

// raster_texcoord: the conversion of v * 128, wrapped to a signed 24-bit field.
VI raster_texcoord(VF v) {
  return hn::ShiftRight<8>(hn::ShiftLeft<8>(x86_float_to_int(hn::Mul(v, kf(128.0f)))));
}

void RunDepths(const Triangle& t, const RunPixels& pixels, RunValues& out) {
  const DF df;
  for (size_t lane = 0; lane < static_cast<size_t>(kPixelLanes); lane += hn::Lanes(df)) {
    const VI z = raster_depth(slope_value(t.z, position(t.origin, pixels, lane)));
    hn::Store(z, DI(), reinterpret_cast<s32*>(out.z) + lane);
  }
}

// raster_pixel's colours and texture coordinates (rasteriser.cpp raster_pixel_attributes).
void RunAttributes(const Triangle& t, const RunPixels& pixels, bool round_colors, RunValues& out) {
  const DF df;
  const DI di;
  for (size_t lane = 0; lane < static_cast<size_t>(kPixelLanes); lane += hn::Lanes(df)) {
    const Position p = position(t.origin, pixels, lane);
    for (int c = 0; c < t.channels; ++c) {
      for (int i = 0; i < 4; ++i) {
        const VF v = slope_value(t.color[static_cast<size_t>(c)][static_cast<size_t>(i)], p);
        hn::Store(round_colors ? rounded_color(v) : raster_color(v), di, out.color[c][i] + lane);
      }
    }
    if (t.texgens == 0) continue;
    // [DSW BuildBlock]: invW = 1 / w; q = tq * invW; projection = invW / q unless q is 0 (Eq,
    // not Ne: a NaN q is not 0 in the scalar, and Eq is false for it on every target).
    const VF inv_w = hn::Div(kf(1.0f), slope_value(t.w, p));
    for (int g = 0; g < t.texgens; ++g) {
      const auto& s = t.tex[static_cast<size_t>(g)];
      const VF q = hn::Mul(slope_value(s[2], p), inv_w);
      const VF projection = hn::IfThenElse(hn::Eq(q, kf(0.0f)), inv_w, hn::Div(inv_w, q));
      hn::Store(raster_texcoord(hn::Mul(slope_value(s[0], p), projection)), di,
                out.uv[g][0] + lane);
      hn::Store(raster_texcoord(hn::Mul(slope_value(s[1], p), projection)), di,
                out.uv[g][1] + lane);
    }
  }
}

}  // namespace lt::gx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lt::gx {

HWY_EXPORT(RunDepths);
HWY_EXPORT(RunAttributes);

void run_depths(const Triangle& t, const RunPixels& pixels, RunValues& out) {
  HWY_DYNAMIC_DISPATCH(RunDepths)(t, pixels, out);
}

void run_attributes(const Triangle& t, const RunPixels& pixels, bool round_colors, RunValues& out) {
  HWY_DYNAMIC_DISPATCH(RunAttributes)(t, pixels, round_colors, out);
}

}  // namespace lt::gx
#endif
