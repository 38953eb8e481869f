#include "model/translucency.h"

#include <algorithm>
#include <cmath>

#include "model/lobe_power.h"
#include "model/texture_sampling.h"

namespace lt::model {

double lobe(double t, double p) {
  if (p == 0) return 1.0;  // 0^0 := 1: the lobe is flat, t plays no part
  if (t <= 0) return 0.0;
  return lobe_power(t, p);
}

LightSample sample_light(const Light& light, const glm::dvec3& P, const glm::dvec3& N) {
  if (light.type == Light::Type::Directional) return {-light.direction, 1.0};
  const glm::dvec3 to_light = light.position - P;
  const double dist = glm::length(to_light);
  const glm::dvec3 L = dist > 0 ? to_light / dist : N;
  const double den = light.kc + light.kl * dist + light.kq * dist * dist;
  return {L, 1.0 / std::max(den, kMinAttenuationDenominator)};
}

double translucency_dot_unsaturated(const glm::dvec3& V, const glm::dvec3& L, const glm::dvec3& N,
                                    const Translucency& tr) {
  glm::dvec3 H = L + N * tr.distortion;
  if (tr.normalize_distorted_light) {
    const double len = glm::length(H);
    H = len > 0 ? H / len : glm::dvec3(0);
  }
  return glm::dot(V, -H);
}

double translucency_dot(const glm::dvec3& V, const glm::dvec3& L, const glm::dvec3& N,
                        const Translucency& tr) {
  return std::clamp(translucency_dot_unsaturated(V, L, N, tr), 0.0, 1.0);
}

glm::dvec3 thickness(const Translucency& tr, const glm::dvec3& vertex_thickness, glm::dvec2 uv) {
  switch (tr.thickness_source) {
    case ThicknessSource::Vertex:
      return vertex_thickness * tr.tint;
    case ThicknessSource::Texture:
      return sample_bilinear(tr.thickness_map->texture, uv) * tr.tint;
    case ThicknessSource::Constant:
      break;
  }
  return tr.thickness * tr.tint;
}

glm::dvec3 diffuse_albedo(const Material& material, glm::dvec2 uv) {
  if (!material.albedo_map) return material.albedo;
  return material.albedo * sample_bilinear(material.albedo_map->texture, uv);
}

glm::dvec3 material_lobe(const Translucency& tr, double t) {
  return tr.ramp ? sample_ramp(tr.ramp->texture, t) : glm::dvec3(lobe(t, tr.power));
}

glm::dvec3 shade(const Scene& scene, const Material& material, const SurfacePoint& sp) {
  const double len = glm::length(sp.N);
  const glm::dvec3 N = len >= kMinNormalLength ? sp.N / len : glm::dvec3(0);
  glm::dvec3 sum(0);
  const glm::dvec3 T = material.translucency
                           ? thickness(*material.translucency, sp.vertex_thickness, sp.uv)
                           : glm::dvec3(0);
  for (const Light& light : scene.lights) {
    const LightSample ls = sample_light(light, sp.P, N);
    glm::dvec3 term(ls.attenuation * std::max(glm::dot(N, ls.L), 0.0));
    if (material.translucency) {
      const Translucency& tr = *material.translucency;
      const double t = translucency_dot(sp.V, ls.L, N, tr);
      term += ls.attenuation * (material_lobe(tr, t) * light.translucency_scale + tr.ambient) * T;
    }
    sum += light.color * term;
  }
  return diffuse_albedo(material, sp.uv) * (scene.ambient_light + sum);
}

std::string why_t_is_not_affine_in_the_normal(const Scene& scene, const Material& material) {
  if (scene.camera.projection != Camera::Projection::Orthographic)
    return "the camera is perspective (V varies over the mesh)";
  for (const Light& l : scene.lights) {
    if (l.type != Light::Type::Directional) return "a point light (L varies over the mesh)";
  }
  if (material.translucency && material.translucency->normalize_distorted_light)
    return "material " + material.name + " normalises H";
  return "";
}

glm::dvec3 view_vector(const Camera& camera, const glm::dvec3& P_rel) {
  if (camera.projection == Camera::Projection::Orthographic) return -camera.forward();
  const double len = glm::length(P_rel);
  // A point exactly at the eye cannot be rasterised (near > 0); guard anyway.
  return len > 0 ? -P_rel / len : -camera.forward();
}

}  // namespace lt::model
