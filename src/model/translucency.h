// The shading model of model.md in double precision: the ground truth every path is judged
// against. Every hard case has one documented result here, and every GPU path mirrors it.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "scene/scene.h"

namespace lt::model {

// Numeric conventions for the hard cases (model.md). The GPU paths implement the same intent.
//
// A normal shorter than this after interpolation is "no normal" (zero-length normals in the mesh,
// or opposite normals cancelling across a triangle): diffuse = 0 and H = L (no distortion).
// 1e-6 is well above the float noise of interpolating unit vectors and far below any normal a
// real mesh interpolates to.
inline constexpr double kMinNormalLength = 1e-6;
// Point-light attenuation denominators are floored here so a light at distance 0 with kc = 0
// gives a large finite value (1e6), never Inf. Validation guarantees kc + kl + kq > 0.
inline constexpr double kMinAttenuationDenominator = 1e-6;

// t^p with 0^0 := 1 and t^p := 0 for t = 0, p > 0; otherwise lobe_power(t, p) (lobe_power.h: a
// whole p correctly rounded, others std::pow). Underflow for huge p is a plain 0, not a denormal
// soup: std::pow does that already in double.
double lobe(double t, double p);

// Unit light direction (towards the light) and attenuation for one light at world point P.
// A point light exactly at P (distance 0) lights P head-on: L = N (or 0 when N is 0).
struct LightSample {
  glm::dvec3 L;
  double attenuation;
};
LightSample sample_light(const Light& light, const glm::dvec3& P, const glm::dvec3& N);

// The translucency factor t = saturate(dot(V, -H)) with H = L + N*d, normalised on request
// (normalize(0) := 0, so a cancelled H gives t = 0 like the unnormalised form).
double translucency_dot(const glm::dvec3& V, const glm::dvec3& L, const glm::dvec3& N,
                        const Translucency& tr);
// dot(V, -H) before the saturate: what per-vertex paths interpolate, so the saturate happens per
// pixel (in the LUT's clamp) as in the per-pixel model; interpolating the clamped value would
// move the lobe's edge.
double translucency_dot_unsaturated(const glm::dvec3& V, const glm::dvec3& L, const glm::dvec3& N,
                                    const Translucency& tr);

// Inputs at a shaded point. N need not be unit (it is renormalised here), V must be unit.
struct SurfacePoint {
  glm::dvec3 P;
  glm::dvec3 N;
  glm::dvec3 V;
  glm::dvec3 vertex_thickness{1, 1, 1};  // interpolated vertex colour (used for "vertex")
  glm::dvec2 uv{0, 0};                   // interpolated UV (used for a thickness or albedo map)
};

// The diffuse albedo at uv: the material's albedo, times its albedo map bilinearly sampled in
// double with the map's wrap modes (load/albedo_map.h) when it has one.
glm::dvec3 diffuse_albedo(const Material& material, glm::dvec2 uv);

// The thickness T of model.md: (vertex colour, the map bilinearly sampled at uv in double, or the
// constant) times tint.
glm::dvec3 thickness(const Translucency& tr, const glm::dvec3& vertex_thickness,
                     glm::dvec2 uv = {0, 0});

// The lobe of one light at t = saturate(...): t^power (lobe above), or the material's ramp at t
// (model/texture_sampling.h: linear between texel centres, clamped), per channel.
glm::dvec3 material_lobe(const Translucency& tr, double t);

// c = albedo * (ambient_light + sum over lights of color * (diffuse + trans)), albedo the
// diffuse_albedo at the point's uv.
glm::dvec3 shade(const Scene& scene, const Material& material, const SurfacePoint& sp);

// Why t = dot(V, -(L + N d)) is not affine in the normal for `material` in this scene (empty when
// it is): only then can fixed-function hardware compute it from the normal through a texture
// matrix (GL texgen, GX texgen), which needs V and L constant over the mesh (an orthographic
// camera, directional lights) and H not normalised.
std::string why_t_is_not_affine_in_the_normal(const Scene& scene, const Material& material);

// View vector for a camera at a point: normalize(E - P), or -forward for orthographic.
// `P_rel` is the point relative to the eye (the paths work camera-relative).
glm::dvec3 view_vector(const Camera& camera, const glm::dvec3& P_rel);

}  // namespace lt::model
