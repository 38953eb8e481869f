// XF lighting (gx-hardware.md §2.3-2.4). The float arithmetic follows Dolphin's software renderer
// [DSW TransformUnit.cpp CalculateLightAttn, LightColor, LightAlpha, TransformColor] operation by
// operation, including the order of the float products, because that renderer is the path's
// bit-level model. The departures are the places where Dolphin would produce NaN (a zero normal,
// a light exactly at the vertex, overflowing coefficients); each is marked "Departure".
#include "gx/xf_lighting.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/error.h"

namespace lt::gx {

namespace {

// Dolphin's Vec3 dot product, x*x' + y*y' + z*z' in this order, in float [DSW Vec3.h].
float dot3(const glm::vec3& a, const glm::vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// max(0, x) as Dolphin's std::max(0.0f, x) evaluates it: NaN gives 0 (the comparison is false).
float positive_part(float x) {
  return x > 0.0f ? x : 0.0f;
}

// Dolphin's SafeDivide [DSW TransformUnit.cpp]: a zero denominator gives 1 for a positive
// numerator, else 0 (no hardware test behind it; it keeps A finite for k = 0).
float safe_divide(float n, float d) {
  if (d == 0.0f) return n > 0.0f ? 1.0f : 0.0f;
  return n / d;
}

// The unit vector along v, computed as Dolphin's Vec3::Normalized: v * (1 / sqrtf(|v|^2)) [DSW
// Vec3.h]. nullopt when v has no direction (zero, or a NaN / infinite component).
// Departure: when |v|^2 underflows to 0 or overflows to infinity although v is finite and
// non-zero, v is first scaled by a power of two (exact, so the direction is unchanged), where
// Dolphin would return NaN or the zero vector.
std::optional<glm::vec3> unit(const glm::vec3& v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return std::nullopt;
  glm::vec3 w = v;
  float len2 = dot3(w, w);
  if (!(len2 > 0.0f) || !std::isfinite(len2)) {
    const float m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
    if (m == 0.0f) return std::nullopt;
    int exponent = 0;
    std::frexp(m, &exponent);  // m = f * 2^exponent, 0.5 <= f < 1
    w = glm::vec3(std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent),
                  std::ldexp(v.z, -exponent));
    len2 = dot3(w, w);  // now in [0.25, 3]
  }
  return w * (1.0f / std::sqrt(len2));
}

// Attenuation A and diffuse factor D of one light at one vertex (§2.3).
struct LightTerms {
  float attenuation = 1.0f, diffuse = 1.0f;
};

LightTerms light_terms(const XfLight& light, const ChannelControl& ctl, const glm::vec3& P,
                       const glm::vec3& N) {
  const glm::vec3 v = light.position - P;
  // Departure: a light exactly at the vertex has no direction (Dolphin computes 0 * inf = NaN);
  // the model's rule for a point light at distance 0 is L = N, which is also what Dolphin's
  // shader backends substitute for NONE/DIR lights [DHW LightingShaderGen GenerateLightShader
  // `if (length(ldir) == 0.0) ldir = _norm0`]. Applied to every attenuation function here, and
  // also to a light whose position is NaN or infinite (no direction either).
  const glm::vec3 l = unit(v).value_or(N);
  LightTerms t;
  switch (ctl.attenuation_fn) {
    case kAttnNone:  // XF "directional": A = 1
      break;
    case kAttnSpot: {
      // dist^2 is |v|^2 itself, not dist*dist, as in DSW CalculateLightAttn.
      const float dist2 = dot3(v, v);
      const float dist = std::sqrt(dist2);
      const float x = positive_part(dot3(l, light.direction));
      const float angular = light.a[0] + light.a[1] * x + light.a[2] * x * x;
      const float distance = light.k[0] + light.k[1] * dist + light.k[2] * dist2;
      t.attenuation = safe_divide(positive_part(angular), distance);
      break;
    }
    case kAttnSpec: {
      // x is N.dir (the half-angle vector in the direction slot), counted only where the light
      // is in front of the surface. The k vector is used as stored: Dolphin's shader path
      // normalises it when the diffuse function is not NONE, which PR#10481 shows is wrong on
      // hardware, and libogc never combines SPEC with a diffuse function (GX_SetChanCtrl forces
      // GX_DF_NONE [OGC gx.c L2195]).
      const float x = dot3(l, N) >= 0.0f ? positive_part(dot3(light.direction, N)) : 0.0f;
      const float x2 = x * x;
      const float angular = 1.0f * light.a[0] + x * light.a[1] + x2 * light.a[2];
      const float distance = 1.0f * light.k[0] + x * light.k[1] + x2 * light.k[2];
      t.attenuation = safe_divide(positive_part(angular), distance);
      break;
    }
    default:
      LT_CHECK(false, "attenuation_fn must be GX_AF_SPEC, GX_AF_SPOT or GX_AF_NONE");
  }
  switch (ctl.diffuse_fn) {
    case kDiffuseNone:
      break;
    case kDiffuseSigned:  // may be negative: a light behind the surface darkens
      t.diffuse = dot3(l, N);
      break;
    case kDiffuseClamp:
      t.diffuse = positive_part(dot3(l, N));
      break;
    default:
      LT_CHECK(false, "diffuse_fn must be GX_DF_NONE, GX_DF_SIGNED or GX_DF_CLAMP");
  }
  return t;
}

// One light's contribution to one component, on the 0..255 scale. The product order follows
// the model being followed, since float products do not associate: DSW LightColor scales the
// colour by (A*D), DSW LightAlpha computes (colour*A)*D, DHW GenerateLightShader (the
// RoundEachLight model) rounds (A*D)*colour. Departure: a NaN product (0 * inf from a huge A,
// a NaN coefficient) counts as no light, so no NaN reaches the sum.
float contribution(u8 light_color, const LightTerms& t, bool diffuse_used, bool alpha,
                   LightRounding rounding) {
  const float c = light_color;
  float value;
  if (!diffuse_used) {
    value = c * t.attenuation;
  } else if (alpha && rounding == LightRounding::SumThenTruncate) {
    value = c * t.attenuation * t.diffuse;
  } else {
    value = c * (t.attenuation * t.diffuse);
  }
  if (std::isnan(value)) return 0.0f;
  if (rounding == LightRounding::RoundEachLight) value = std::round(value);
  return value;
}

// The accumulated light to the integer 0..255 that enters the material multiply. DSW converts
// with static_cast<int> (truncation toward zero) and then clamps; clamping in floating point
// first gives the same integer for every finite value and keeps out-of-range and infinite sums
// defined (converting them to int would be undefined). Departure: NaN (inf - inf) gives 0.
int to_light_level(double sum) {
  if (!(sum > 0.0)) return 0;  // also NaN
  if (sum >= 255.0) return 255;
  return static_cast<int>(sum);
}

// (mat * (l + (l >> 7))) >> 8: the hardware's approximation of mat * l / 255, HW-verified for
// the no-light case over all 65536 pairs [HWT gxtest/lighting.cpp L86] [DSW TransformColor].
u8 modulate(u8 material, int level) {
  return static_cast<u8>((material * (level + (level >> 7))) >> 8);
}

// Components [first, first + count) of channel `ch` under one control (COLORn: r, g, b;
// ALPHAn: a). Colour and alpha are independent: each has its own control, lights and sources.
void light_components(const XfLightingState& state, const ChannelControl& ctl, int ch, int first,
                      int count, const glm::vec3& P, const glm::vec3& N, const Color8& vertex,
                      LightRounding rounding, Color8& out) {
  LT_CHECK(ctl.material_source == kSrcReg || ctl.material_source == kSrcVtx,
           "material_source must be GX_SRC_REG or GX_SRC_VTX");
  LT_CHECK(ctl.ambient_source == kSrcReg || ctl.ambient_source == kSrcVtx,
           "ambient_source must be GX_SRC_REG or GX_SRC_VTX");
  const Color8& material = ctl.material_source == kSrcVtx ? vertex : state.material[ch];
  if (!ctl.lighting) {  // the material passes unchanged [DSW TransformColor]
    for (int k = first; k < first + count; ++k) out[k] = material[k];
    return;
  }
  const Color8& ambient = ctl.ambient_source == kSrcVtx ? vertex : state.ambient[ch];
  const bool alpha = first == 3;
  // SumThenTruncate accumulates in float, exactly as DSW's `lightCol`. RoundEachLight adds
  // integers (DHW `lacc`, an int4), held in a double so no sum of rounded floats can overflow.
  const bool truncate = rounding == LightRounding::SumThenTruncate;
  float fsum[4] = {0, 0, 0, 0};
  double isum[4] = {0, 0, 0, 0};
  for (int k = first; k < first + count; ++k) {
    fsum[k] = ambient[k];
    isum[k] = ambient[k];
  }
  for (int n = 0; n < kMaxLights; ++n) {
    if ((ctl.light_mask & (1u << n)) == 0) continue;
    const XfLight& light = state.lights[n];
    const LightTerms t = light_terms(light, ctl, P, N);
    for (int k = first; k < first + count; ++k) {
      const float c =
          contribution(light.color[k], t, ctl.diffuse_fn != kDiffuseNone, alpha, rounding);
      if (truncate) {
        fsum[k] += c;
      } else {
        isum[k] += c;
      }
    }
  }
  for (int k = first; k < first + count; ++k) {
    const double sum = truncate ? fsum[k] : isum[k];
    // The clamp precedes the material multiply, so lightcolor * A > 255 saturates (§2.4).
    out[k] = modulate(material[k], to_light_level(sum));
  }
}

}  // namespace

std::array<Color8, kMaxChannels> light_vertex(const XfLightingState& state,
                                              const glm::vec3& position, const glm::vec3& normal,
                                              const std::array<Color8, kMaxChannels>& vertex_colors,
                                              LightRounding rounding) {
  LT_CHECK(state.num_channels >= 0 && state.num_channels <= kMaxChannels,
           "num_channels must be 0, 1 or 2 (GX_SetNumChans)");
  // DSW TransformNormal normalises the lighting normal. Departure: a zero (or NaN / infinite)
  // normal has no direction; N = 0 makes every diffuse factor and the SPEC x zero instead of
  // NaN.
  const glm::vec3 N = unit(normal).value_or(glm::vec3(0.0f));
  std::array<Color8, kMaxChannels> out{};  // channels beyond num_channels stay {0, 0, 0, 0}
  for (int ch = 0; ch < state.num_channels; ++ch) {
    light_components(state, state.control[ch], ch, 0, 3, position, N, vertex_colors[ch], rounding,
                     out[ch]);
    light_components(state, state.control[2 + ch], ch, 3, 1, position, N, vertex_colors[ch],
                     rounding, out[ch]);
  }
  return out;
}

}  // namespace lt::gx
