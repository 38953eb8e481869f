// The half path's shading, a run of pixels at a time: model.md in binary16 as half_shading.cpp's
// file comment describes it, one pixel a lane. Compiled once per Highway target
// (hwy/foreach_target.h re-includes this file); outside the unity build (CMakeLists.txt), since
// the re-inclusion needs a translation unit of its own.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "paths/half/half_shading_lanes.cpp"
#include "paths/half/half_shading_lanes.h"

#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "core/error.h"
#include "model/texture_sampling.h"
#include "paths/half/half_rounding-inl.h"

HWY_BEFORE_NAMESPACE();
namespace lt::fp16::HWY_NAMESPACE {

using D = hn::ScalableTag<float>;
using V = hn::Vec<D>;

struct V3 {
  V x, y, z;
};

// The arithmetic of one mode on lanes, operation for operation half_shading.cpp's Fp16: IEEE
// half (unguarded) or saturating half (guarded), each result rounded once from float.
class Lanes16 {
 public:
  explicit Lanes16(bool guarded) : guarded_(guarded) {}
  bool guarded() const { return guarded_; }
  static size_t count() { return hn::Lanes(D()); }

  static V k(float x) { return hn::Set(D(), x); }
  static V k(half h) { return k(float(h)); }
  static V3 k(const Vec3h& v) { return {k(v.x), k(v.y), k(v.z)}; }
  // A G-buffer value rounded to half as the shader receives it: plain IEEE (no saturation),
  // as half_shading.cpp's to_half.
  static V input(const float* lanes) { return RoundToHalf(D(), hn::Load(D(), lanes)); }

  V r(V x) const {
    if (guarded_) {
      x = hn::IfThenElse(hn::Gt(x, k(kHalfMax)), k(kHalfMax), x);
      x = hn::IfThenElse(hn::Lt(x, k(-kHalfMax)), k(-kHalfMax), x);
    }
    return RoundToHalf(D(), x);
  }
  V add(V a, V b) const { return r(hn::Add(a, b)); }
  V sub(V a, V b) const { return r(hn::Sub(a, b)); }
  V mul(V a, V b) const { return r(hn::Mul(a, b)); }
  V div(V a, V b) const { return r(hn::Div(a, b)); }
  V sqrt(V a) const { return r(hn::Sqrt(a)); }
  V rsqrt(V a) const { return r(hn::Div(k(1.0f), hn::Sqrt(a))); }
  // exp2 and log2 as before, std:: in float a lane at a time (no vector exp2 that is std's to
  // the bit), then rounded.
  V exp2(V a) const {
    return r(each_lane(a, [](float x) { return std::exp2(x); }));
  }
  V log2(V a) const {
    return r(each_lane(a, [](float x) { return std::log2(x); }));
  }
  // NaN compares false, so NaN -> 0 (D3D10+ saturate/max rule).
  static V max0(V a) { return hn::IfThenElseZero(hn::Gt(a, hn::Zero(D())), a); }
  static V saturate(V a) { return hn::IfThenElse(hn::Gt(a, k(1.0f)), k(1.0f), max0(a)); }

  V3 add(const V3& a, const V3& b) const { return {add(a.x, b.x), add(a.y, b.y), add(a.z, b.z)}; }
  V3 sub(const V3& a, const V3& b) const { return {sub(a.x, b.x), sub(a.y, b.y), sub(a.z, b.z)}; }
  V3 mul(const V3& a, const V3& b) const { return {mul(a.x, b.x), mul(a.y, b.y), mul(a.z, b.z)}; }
  V3 mul(const V3& a, V s) const { return {mul(a.x, s), mul(a.y, s), mul(a.z, s)}; }
  // DP3 as three rounded products and two rounded sums.
  V dot(const V3& a, const V3& b) const {
    return add(add(mul(a.x, b.x), mul(a.y, b.y)), mul(a.z, b.z));
  }
  static V3 neg(const V3& a) { return {hn::Neg(a.x), hn::Neg(a.y), hn::Neg(a.z)}; }

  // v * rsqrt(dot(v, v)), or `fallback` in the lanes whose squared length is not a normal half
  // (guarded). Unguarded: 0 * rsqrt(0) = 0 * Inf = NaN.
  V3 normalize(const V3& v, const V3& fallback) const {
    const V len2 = dot(v, v);
    const V3 unit = mul(v, rsqrt(len2));
    if (!guarded_) return unit;
    const auto normal = hn::Ge(len2, k(kHalfMinNormal));
    return {hn::IfThenElse(normal, unit.x, fallback.x), hn::IfThenElse(normal, unit.y, fallback.y),
            hn::IfThenElse(normal, unit.z, fallback.z)};
  }

  // A texture unit's bilinear sample at each lane's (u, v) (sample_half in half_shading.h):
  // the taps and fractions are the unit's addressing (model::bilinear_taps, a lane at a time);
  // each weight (fx, 1 - fx, fy, 1 - fy) is rounded to half and the blend
  // ((1-fy)((1-fx) t00 + fx t10) + fy((1-fx) t01 + fx t11)) rounds every product and sum.
  V3 sample(const TextureH& t, const glm::dvec2* uv) const {
    alignas(64) float fx[kPixelRunCapacity], fy[kPixelRunCapacity];
    alignas(64) float texels[4][3][kPixelRunCapacity];  // t00, t10, t01, t11
    for (size_t i = 0; i < count(); ++i) {
      const model::BilinearTaps taps =
          model::bilinear_taps(t.width, t.height, uv[i], t.wrap_s, t.wrap_t);
      fx[i] = static_cast<float>(taps.fx);  // to half below through float, as to_half(double)
      fy[i] = static_cast<float>(taps.fy);
      const int xs[4] = {taps.x0, taps.x1, taps.x0, taps.x1};
      const int ys[4] = {taps.y0, taps.y0, taps.y1, taps.y1};
      for (int tap = 0; tap < 4; ++tap) {
        const Vec3h& texel = t.texels[static_cast<size_t>(ys[tap]) * t.width + xs[tap]];
        texels[tap][0][i] = float(texel.x);
        texels[tap][1][i] = float(texel.y);
        texels[tap][2][i] = float(texel.z);
      }
    }
    auto tap = [&](int n) {
      return V3{hn::Load(D(), texels[n][0]), hn::Load(D(), texels[n][1]),
                hn::Load(D(), texels[n][2])};
    };
    const V wx = input(fx), wy = input(fy);  // a weight is rounded to half as it is, no saturation
    const V gx = sub(k(1.0f), wx), gy = sub(k(1.0f), wy);
    const V3 bottom = add(mul(tap(0), gx), mul(tap(1), wx));
    const V3 top = add(mul(tap(2), gx), mul(tap(3), wx));
    return add(mul(bottom, gy), mul(top, wy));
  }
  // The same at the lanes' (u, v) as floats (the G-buffer's, or a ramp's (t, 0.5)).
  V3 sample(const TextureH& t, V u, V v) const {
    alignas(64) float us[kPixelRunCapacity], vs[kPixelRunCapacity];
    hn::Store(u, D(), us);
    hn::Store(v, D(), vs);
    glm::dvec2 uv[kPixelRunCapacity];
    for (size_t i = 0; i < count(); ++i) uv[i] = {us[i], vs[i]};
    return sample(t, uv);
  }

 private:
  template <class F>
  static V each_lane(V a, F f) {
    alignas(64) float lanes[kPixelRunCapacity];
    hn::Store(a, D(), lanes);
    for (size_t i = 0; i < count(); ++i) lanes[i] = f(lanes[i]);
    return hn::Load(D(), lanes);
  }

  bool guarded_;
};

// t^p per mode (the seed's pow(saturate(...), iLTPower)).
V lobe(const Lanes16& f, const MaterialH& m, PowMode mode, V t) {
  if (mode == PowMode::Unguarded)
    return f.exp2(f.mul(Lanes16::k(m.power), f.log2(t)));  // 0^0 = NaN
  if (float(m.power) == 0) return Lanes16::k(1.0f);        // 0^0 := 1: the lobe is flat
  if (mode == PowMode::Sg) {
    // exp2(t * n' - n') as MUL then SUB (t <= 1, so the argument is <= 0: exp2 cannot overflow
    // half's 16; for large n' it underflows to 0 like pow).
    const V n = Lanes16::k(m.sg_exponent);
    return f.exp2(f.sub(f.mul(t, n), n));
  }
  // POW = EX2(p * LG2(t)); LG2(0) = -Inf, so t = 0 takes the model's 0. p * log2(t) <= 0, and
  // underflows (0.5^1024) round to 0 through half's subnormals. No lane with t > 0: all 0, and
  // the per-lane exp2 and log2 are not called.
  const auto lit = hn::Gt(t, hn::Zero(D()));
  if (hn::AllFalse(D(), lit)) return hn::Zero(D());
  return hn::IfThenElseZero(lit, f.exp2(f.mul(Lanes16::k(m.power), f.log2(t))));
}

// The lanes of `run` from index o: the seed's shader, a pixel a lane.
V3 shade_lanes(const SceneH& scene, const MaterialH& m, PowMode mode, const PixelRun& run,
               size_t o) {
  const Lanes16 f(mode != PowMode::Unguarded);
  using A = Lanes16;
  const V3 zero{hn::Zero(D()), hn::Zero(D()), hn::Zero(D())};
  // A half-precision pipeline sees its G-buffer in half: round the inputs first. Positions are
  // camera-relative, so a scene at 1e6 still has small numbers here.
  const V3 P{A::input(run.position[0] + o), A::input(run.position[1] + o),
             A::input(run.position[2] + o)};
  const V3 N = f.normalize(
      {A::input(run.normal[0] + o), A::input(run.normal[1] + o), A::input(run.normal[2] + o)},
      zero);
  const V3 view_dir = A::k(scene.view_dir);
  const V3 eye = scene.orthographic ? view_dir : f.normalize(A::neg(P), view_dir);
  const V u = hn::Load(D(), run.uv[0] + o), v = hn::Load(D(), run.uv[1] + o);
  V3 T = zero;
  if (m.translucent) {
    if (m.map_thickness) {
      T = f.mul(f.sample(m.map, u, v), A::k(m.thickness));
    } else if (m.vertex_thickness) {
      const V3 vertex{A::input(run.thickness[0] + o), A::input(run.thickness[1] + o),
                      A::input(run.thickness[2] + o)};
      T = f.mul(vertex, A::k(m.thickness));
    } else {
      T = A::k(m.thickness);
    }
  }

  V3 sum = zero;
  for (const LightH& l : scene.lights) {
    V3 Ld = A::k(l.to_light);
    V att = A::k(1.0f);
    if (l.point) {
      const V3 d = f.sub(A::k(l.position), P);
      const V dist = f.sqrt(f.dot(d, d));
      Ld = f.normalize(d, N);  // guarded: a light "at" the point lights it head-on (L = N)
      // kc + kl*dist + kq*dist^2, step by step.
      const V den =
          f.add(f.add(A::k(l.kc), f.mul(A::k(l.kl), dist)), f.mul(f.mul(A::k(l.kq), dist), dist));
      // Guarded: att <= 65504 (denominator floored at 1/65504, see half_shading.cpp).
      // Unguarded: 1/0 = Inf, and anything below 1/65504 overflows to Inf too.
      att = f.div(A::k(1.0f), den);
      if (f.guarded())
        att = hn::IfThenElse(hn::Gt(den, A::k(1.0f / kHalfMax)), att, A::k(kHalfMax));
    }
    const V diffuse = f.mul(att, A::max0(f.dot(N, Ld)));
    V3 term{diffuse, diffuse, diffuse};
    if (m.translucent) {
      // half3 vLTLight = vLight + vNormal * fLTDistortion;
      V3 H = f.add(Ld, f.mul(N, A::k(m.distortion)));
      if (m.normalize_h) H = f.normalize(H, zero);
      // half fLTDot = pow(saturate(dot(vEye, -vLTLight)), iLTPower) * fLTScale;
      const V t = A::saturate(f.dot(eye, A::neg(H)));
      // A ramp material: tex2D(ramp, float2(t, 0.5)).rgb instead of the pow, per channel.
      V3 lobe3;
      if (m.ramp_lobe) {
        lobe3 = f.sample(m.ramp, t, A::k(0.5f));
      } else {
        const V p = lobe(f, m, mode, t);
        lobe3 = {p, p, p};
      }
      const V3 lt_dot = f.mul(lobe3, A::k(l.scale));
      // half3 fLT = fLightAttenuation * (fLTDot + fLTAmbient) * fLTThickness;
      const V ambient = A::k(m.ambient);
      const V3 lt =
          f.mul(T, V3{f.mul(att, f.add(lt_dot.x, ambient)), f.mul(att, f.add(lt_dot.y, ambient)),
                      f.mul(att, f.add(lt_dot.z, ambient))});
      term = f.add(term, lt);
    }
    // outColor.rgb += cDiffuseAlbedo * cLightDiffuse * fLT; (albedo applied once, below, in the
    // model's order: c = albedo * (ambient_light + sum of color * (diffuse + trans)).)
    sum = f.add(sum, f.mul(A::k(l.color), term));
  }
  // The seed's cDiffuseAlbedo from a texture: tex2D(albedo, uv).rgb * albedo, in half.
  const V3 albedo =
      m.albedo_mapped ? f.mul(f.sample(m.albedo_map, u, v), A::k(m.albedo)) : A::k(m.albedo);
  return f.mul(albedo, f.add(A::k(scene.ambient_light), sum));
}

void ShadeRun(const SceneH& scene, const MaterialH& m, PowMode mode, const PixelRun& run,
              ShadedRun& out) {
  const size_t n = Lanes16::count();
  LT_CHECK(kPixelRunPadding % n == 0, "a run is padded to whole vectors");
  for (size_t o = 0; o < run.count; o += n) {
    const V3 c = shade_lanes(scene, m, mode, run, o);
    hn::Store(c.x, D(), out.rgb[0] + o);
    hn::Store(c.y, D(), out.rgb[1] + o);
    hn::Store(c.z, D(), out.rgb[2] + o);
  }
}

void RoundToHalfArray(const float* in, float* out, size_t n) {
  const D d;
  size_t i = 0;
  for (; i + hn::Lanes(d) <= n; i += hn::Lanes(d))
    hn::StoreU(RoundToHalf(d, hn::LoadU(d, in + i)), d, out + i);
  const hn::CappedTag<float, 1> d1;
  for (; i < n; ++i) hn::StoreU(RoundToHalf(d1, hn::LoadU(d1, in + i)), d1, out + i);
}

// One sample at `uv`, in every lane; lane 0's value.
void SampleOne(const TextureH& texture, glm::dvec2 uv, bool guarded, float* rgb) {
  glm::dvec2 uvs[kPixelRunCapacity];
  for (glm::dvec2& x : uvs) x = uv;
  const V3 s = Lanes16(guarded).sample(texture, uvs);
  rgb[0] = hn::GetLane(s.x);
  rgb[1] = hn::GetLane(s.y);
  rgb[2] = hn::GetLane(s.z);
}

}  // namespace lt::fp16::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lt::fp16 {

HWY_EXPORT(ShadeRun);
HWY_EXPORT(RoundToHalfArray);
HWY_EXPORT(SampleOne);

Vec3h sample_half(const TextureH& texture, glm::dvec2 uv, bool guarded) {
  float rgb[3];
  HWY_DYNAMIC_DISPATCH(SampleOne)(texture, uv, guarded, rgb);
  return {half(rgb[0]), half(rgb[1]), half(rgb[2])};  // exact: each is a half already
}

void shade_run(const SceneH& scene, const MaterialH& material, PowMode mode, const PixelRun& run,
               ShadedRun& out) {
  HWY_DYNAMIC_DISPATCH(ShadeRun)(scene, material, mode, run, out);
}

void round_to_half(const float* in, float* out, std::size_t n) {
  HWY_DYNAMIC_DISPATCH(RoundToHalfArray)(in, out, n);
}

}  // namespace lt::fp16
#endif  // HWY_ONCE
