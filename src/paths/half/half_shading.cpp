// fp16 evaluation of model.md. Conventions (each one the fp16 form of a rule in
// src/model/translucency.h; the why is at the code):
//
// - Rounding: every operation is done in float and rounded once to half. float has 24 bits >=
//   2 * 11 + 2, so for + - * / sqrt this double rounding equals one correct half rounding.
//   A real fp16 ALU may fuse a multiply-add or a dot product; rounding each step is the
//   conservative (worst-case) emulation. exp2/log2 are correctly rounded here; hardware's are
//   within a few half ulps of that.
// - Overflow: in the guarded modes a result beyond +-65504 saturates to +-65504 (the largest
//   finite half) instead of becoming Inf: an HDR sum over 65504 stays "very bright", as in the
//   reference, and never turns into Inf * 0 = NaN further on. Unguarded rounding is plain IEEE.
// - Normalising: a vector whose squared length is below the smallest normal half (6.1e-5, i.e.
//   length < 0.0078) cannot be normalised in fp16: its squared length is 0 or a subnormal with
//   fewer than 10 bits, so v * rsqrt(dot(v, v)) is Inf or far from unit. Such a vector takes the
//   model's zero-vector convention. This moves the reference's "no normal" threshold (length
//   1e-6, itself below half's resolution) up to 0.0078: a normal that short is "no normal".
//     N -> 0 (diffuse 0, H = L); L of a point light -> N (the light is "at" the point);
//     normalised H -> 0 (t = 0); perspective V -> -forward (the point is "at" the eye).
// - Attenuation: the reference floors the denominator at 1e-6, but 1e-6 is a half subnormal and
//   1/1e-6 overflows half. The fp16 form clamps att at 65504 instead (the denominator is
//   floored at 1/65504): a light at distance 0 stays the brightest value half can hold.
// - 0^0 := 1 and t = 0 -> 0 exactly as the reference (log2(0) = -Inf, and 0 * -Inf is NaN).
// - saturate() and max(x, 0) return 0 for NaN, as D3D10+ and GLSL hardware do; only the
//   unguarded mode can produce a NaN for them to see.
#include "paths/half/half_shading.h"

#include <cmath>

#include "model/pow_curves.h"
#include "model/texture_sampling.h"
#include "model/translucency.h"

namespace lt::fp16 {

namespace {

// The arithmetic of one mode for the scene's constants: IEEE half (unguarded) or saturating
// half (guarded). The shading's and the texture units', on lanes, is half_shading_lanes.cpp's
// Lanes16, operation for operation the same rules.
class Fp16 {
 public:
  explicit Fp16(bool guarded) : guarded_(guarded) {}

  half r(float x) const {
    if (guarded_ && x > kHalfMax) return half(kHalfMax);
    if (guarded_ && x < -kHalfMax) return half(-kHalfMax);
    return half(x);
  }
  half add(half a, half b) const { return r(float(a) + float(b)); }
  half mul(half a, half b) const { return r(float(a) * float(b)); }

 private:
  bool guarded_;
};

Vec3h to_half(const glm::dvec3& v) {
  return {half(static_cast<float>(v.x)), half(static_cast<float>(v.y)),
          half(static_cast<float>(v.z))};
}
Vec3h to_half(const float* v) {
  return {half(v[0]), half(v[1]), half(v[2])};
}
half to_half(double v) {
  return half(static_cast<float>(v));
}

TextureH to_half(const model::Texture& t) {
  TextureH h{t.width, t.height, {}, t.wrap_s, t.wrap_t};
  h.texels.reserve(t.texels.size() / 3);
  for (size_t i = 0; i < t.texels.size(); i += 3) h.texels.push_back(to_half(&t.texels[i]));
  return h;
}

}  // namespace

SceneH prepare_scene(const Scene& scene, PowMode mode) {
  const Fp16 f(mode != PowMode::Unguarded);
  SceneH out;
  out.ambient_light = to_half(scene.ambient_light);
  out.orthographic = scene.camera.projection == Camera::Projection::Orthographic;
  out.view_dir = to_half(-scene.camera.forward());
  for (const Light& l : scene.lights) {
    LightH h;
    h.point = l.type == Light::Type::Point;
    h.to_light = to_half(-l.direction);
    h.position = to_half(l.position);
    h.color = to_half(l.color);
    h.scale = to_half(l.translucency_scale);
    h.kc = to_half(l.kc);
    h.kl = to_half(l.kl);
    h.kq = to_half(l.kq);
    out.lights.push_back(h);
  }
  for (const Material& m : scene.materials) {
    MaterialH h;
    h.albedo = to_half(m.albedo);
    h.albedo_mapped = m.albedo_map != nullptr;
    if (h.albedo_mapped) h.albedo_map = to_half(m.albedo_map->texture);
    if (m.translucency) {
      const Translucency& tr = *m.translucency;
      h.translucent = true;
      h.vertex_thickness = tr.thickness_source == ThicknessSource::Vertex;
      h.normalize_h = tr.normalize_distorted_light;
      h.power = to_half(tr.power);
      h.distortion = to_half(tr.distortion);
      h.ambient = to_half(tr.ambient);
      // The blog's n = n * 1.4427f + 1.4427f, in half like the rest of the shader.
      const half k = to_half(model::kSeedLog2e);
      h.sg_exponent = f.add(f.mul(h.power, k), k);
      h.map_thickness = tr.thickness_source == ThicknessSource::Texture;
      if (h.map_thickness) h.map = to_half(tr.thickness_map->texture);
      h.ramp_lobe = tr.ramp != nullptr;
      if (h.ramp_lobe) h.ramp = to_half(tr.ramp->texture);
      h.thickness = h.vertex_thickness || h.map_thickness ? to_half(tr.tint)
                                                          : to_half(tr.thickness * tr.tint);
    }
    out.materials.push_back(h);
  }
  return out;
}

}  // namespace lt::fp16
