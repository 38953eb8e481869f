// model::shade in double vector lanes, a run of pixels at a time. Compiled once per Highway
// target (hwy/foreach_target.h re-includes this file), outside the unity build (CMakeLists.txt).
// Each step names the scalar line of model/translucency.cpp it mirrors: the order of every
// operation is that line's, since a different order would round differently.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "paths/reference/reference_shading_lanes.cpp"
#include "paths/reference/reference_shading_lanes.h"

#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include <cmath>

#include "core/error.h"
#include "model/lobe_power-inl.h"
#include "model/texture_sampling.h"
#include "model/translucency.h"
#include "paths/reference/bilinear_lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace lt::reference::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<double>;
using V = hn::Vec<D>;

V k(double x) {
  return hn::Set(D(), x);
}

struct V3 {
  V x, y, z;
};

V3 k(const glm::dvec3& v) {
  return {k(v.x), k(v.y), k(v.z)};
}
V3 add(const V3& a, const V3& b) {
  return {hn::Add(a.x, b.x), hn::Add(a.y, b.y), hn::Add(a.z, b.z)};
}
V3 sub(const V3& a, const V3& b) {
  return {hn::Sub(a.x, b.x), hn::Sub(a.y, b.y), hn::Sub(a.z, b.z)};
}
V3 mul(const V3& a, const V3& b) {
  return {hn::Mul(a.x, b.x), hn::Mul(a.y, b.y), hn::Mul(a.z, b.z)};
}
V3 mul(const V3& a, V s) {
  return {hn::Mul(a.x, s), hn::Mul(a.y, s), hn::Mul(a.z, s)};
}
V3 add(const V3& a, V s) {
  return {hn::Add(a.x, s), hn::Add(a.y, s), hn::Add(a.z, s)};
}
V3 div(const V3& a, V s) {
  return {hn::Div(a.x, s), hn::Div(a.y, s), hn::Div(a.z, s)};
}
V3 neg(const V3& a) {
  return {hn::Neg(a.x), hn::Neg(a.y), hn::Neg(a.z)};
}
template <class M>
V3 select(M m, const V3& yes, const V3& no) {
  return {hn::IfThenElse(m, yes.x, no.x), hn::IfThenElse(m, yes.y, no.y),
          hn::IfThenElse(m, yes.z, no.z)};
}
// glm::dot: the products, then (x + y) + z.
V dot(const V3& a, const V3& b) {
  return hn::Add(hn::Add(hn::Mul(a.x, b.x), hn::Mul(a.y, b.y)), hn::Mul(a.z, b.z));
}
// glm::length: sqrt(dot(v, v)).
V length(const V3& v) {
  return hn::Sqrt(dot(v, v));
}
// std::max(a, b) is (a < b) ? b : a, NaN and -0 included.
V max(V a, V b) {
  return hn::IfThenElse(hn::Lt(a, b), b, a);
}

// n floats of the run from index o, widened.
V widen(const float* lanes) {
  return hn::PromoteTo(D(), hn::Load(hn::Rebind<float, D>(), lanes));
}
V3 widen3(const float (&a)[3][kPixelRunCapacity], size_t o) {
  return {widen(a[0] + o), widen(a[1] + o), widen(a[2] + o)};
}

// A scalar function of model/ applied a lane at a time.
template <class F>
V3 each_lane3(F f) {
  alignas(64) double rgb[3][kPixelRunCapacity];
  for (size_t i = 0; i < hn::Lanes(D()); ++i) {
    const glm::dvec3 c = f(i);
    for (int ch = 0; ch < 3; ++ch) rgb[ch][i] = c[ch];
  }
  return {hn::Load(D(), rgb[0]), hn::Load(D(), rgb[1]), hn::Load(D(), rgb[2])};
}
// model::sample_bilinear at the run's (u, v) from lane o on (bilinear_lanes-inl.h).
V3 sample_map(const model::Texture& texture, const PixelRun& run, size_t o) {
  V rgb[3];
  SampleBilinear(D(), texture, widen(run.uv[0] + o), widen(run.uv[1] + o), rgb);
  return {rgb[0], rgb[1], rgb[2]};
}

V3 shade_lanes(const Scene& scene, const Material& material, const PixelRun& run, size_t o) {
  const V zero = hn::Zero(D());
  const V3 zero3{zero, zero, zero};
  const V3 P = widen3(run.position, o);
  // view_vector: -forward (orthographic), else len > 0 ? -P_rel / len : -forward.
  const V3 forward_back = k(-scene.camera.forward());
  V3 view = forward_back;
  if (scene.camera.projection != Camera::Projection::Orthographic) {
    const V len = length(P);
    view = select(hn::Gt(len, zero), div(neg(P), len), forward_back);
  }
  // shade: N = len >= kMinNormalLength ? sp.N / len : 0.
  const V3 normal = widen3(run.normal, o);
  const V normal_length = length(normal);
  const V3 N =
      select(hn::Ge(normal_length, k(model::kMinNormalLength)), div(normal, normal_length), zero3);
  // T = thickness(tr, vertex_thickness, uv): source * tint.
  V3 T = zero3;
  const Translucency* tr = material.translucency ? &*material.translucency : nullptr;
  if (tr) {
    switch (tr->thickness_source) {
      case ThicknessSource::Vertex:
        T = mul(widen3(run.thickness, o), k(tr->tint));
        break;
      case ThicknessSource::Texture:
        T = mul(sample_map(tr->thickness_map->texture, run, o), k(tr->tint));
        break;
      case ThicknessSource::Constant:
        T = k(tr->thickness * tr->tint);
        break;
    }
  }
  V3 sum = zero3;
  for (const Light& light : scene.lights) {
    // sample_light.
    V3 L = k(-light.direction);
    V attenuation = k(1.0);
    if (light.type != Light::Type::Directional) {
      const V3 to_light = sub(k(light.position), P);
      const V dist = length(to_light);
      L = select(hn::Gt(dist, zero), div(to_light, dist), N);
      const V den = hn::Add(hn::Add(k(light.kc), hn::Mul(k(light.kl), dist)),
                            hn::Mul(hn::Mul(k(light.kq), dist), dist));
      attenuation = hn::Div(k(1.0), max(den, k(model::kMinAttenuationDenominator)));
    }
    // term(att * max(dot(N, L), 0)).
    const V diffuse = hn::Mul(attenuation, max(dot(N, L), zero));
    V3 term{diffuse, diffuse, diffuse};
    if (tr) {
      // translucency_dot: H = L + N * d, normalised on request; clamp(dot(V, -H), 0, 1).
      V3 H = add(L, mul(N, k(tr->distortion)));
      if (tr->normalize_distorted_light) {
        const V len = length(H);
        H = select(hn::Gt(len, zero), div(H, len), zero3);
      }
      V t = dot(view, neg(H));
      t = hn::IfThenElse(hn::Lt(t, zero), zero, hn::IfThenElse(hn::Lt(k(1.0), t), k(1.0), t));
      // material_lobe: the ramp at t, or lobe(t, p) (0^0 := 1, t <= 0 -> 0, else lobe_power).
      V3 lobe3;
      if (tr->ramp) {
        alignas(64) double ts[kPixelRunCapacity];
        hn::Store(t, D(), ts);
        lobe3 = each_lane3([&](size_t i) { return model::sample_ramp(tr->ramp->texture, ts[i]); });
      } else if (tr->power == 0) {
        lobe3 = {k(1.0), k(1.0), k(1.0)};
      } else {
        // lobe_power only where lobe() calls it: a lane whose t <= 0 takes 0 below whatever
        // stands in it (a NaN t, which is not <= 0, still goes through lobe_power as in lobe()).
        const auto positive = hn::Not(hn::Le(t, zero));
        const V lobe = hn::IfThenElseZero(
            positive, model::HWY_NAMESPACE::LobePower(D(), t, tr->power, positive));
        lobe3 = {lobe, lobe, lobe};
      }
      // term += att * (lobe * scale + ambient) * T.
      const V3 inner = add(mul(lobe3, k(light.translucency_scale)), k(tr->ambient));
      term = add(term, mul(mul(inner, attenuation), T));
    }
    // sum += color * term.
    sum = add(sum, mul(k(light.color), term));
  }
  // diffuse_albedo(material, uv) * (ambient_light + sum); a map's albedo is albedo * sample.
  V3 albedo = k(material.albedo);
  if (material.albedo_map) {
    albedo = mul(albedo, sample_map(material.albedo_map->texture, run, o));
  }
  return mul(albedo, add(k(scene.ambient_light), sum));
}

void ShadeRun(const Scene& scene, const Material& material, const PixelRun& run, ShadedRun& out) {
  const D d;
  const hn::Rebind<float, D> df;
  const size_t n = hn::Lanes(d);
  LT_CHECK(kPixelRunPadding % n == 0, "a run is padded to whole vectors");
  for (size_t o = 0; o < run.count; o += n) {
    const V3 c = shade_lanes(scene, material, run, o);
    hn::Store(hn::DemoteTo(df, c.x), df, out.rgb[0] + o);
    hn::Store(hn::DemoteTo(df, c.y), df, out.rgb[1] + o);
    hn::Store(hn::DemoteTo(df, c.z), df, out.rgb[2] + o);
  }
}

void SampleBilinearArray(const model::Texture& texture, const double* u, const double* v,
                         double* rgb, size_t n) {
  const hn::CappedTag<double, 1> d1;
  const D d;
  size_t i = 0;
  const auto store = [&](auto dd, size_t at, auto(&c)[3]) {
    for (int ch = 0; ch < 3; ++ch) hn::StoreU(c[ch], dd, rgb + ch * n + at);
  };
  for (; i + hn::Lanes(d) <= n; i += hn::Lanes(d)) {
    V c[3];
    SampleBilinear(d, texture, hn::LoadU(d, u + i), hn::LoadU(d, v + i), c);
    store(d, i, c);
  }
  for (; i < n; ++i) {
    hn::Vec<decltype(d1)> c[3];
    SampleBilinear(d1, texture, hn::LoadU(d1, u + i), hn::LoadU(d1, v + i), c);
    store(d1, i, c);
  }
}

}  // namespace lt::reference::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lt::reference {

HWY_EXPORT(ShadeRun);
HWY_EXPORT(SampleBilinearArray);

void sample_bilinear(const model::Texture& texture, const double* u, const double* v, double* rgb,
                     size_t n) {
  HWY_DYNAMIC_DISPATCH(SampleBilinearArray)(texture, u, v, rgb, n);
}

void shade_run(const Scene& scene, const Material& material, const PixelRun& run, ShadedRun& out) {
  HWY_DYNAMIC_DISPATCH(ShadeRun)(scene, material, run, out);
}

}  // namespace lt::reference
#endif  // HWY_ONCE
