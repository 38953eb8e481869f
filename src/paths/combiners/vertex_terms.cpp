#include "paths/combiners/vertex_terms.h"

#include <algorithm>

#include "combiner/combiner_program.h"
#include "model/translucency.h"
#include "paths/combiners/map_stage.h"

namespace lt {

glm::dvec3 lobe_constant(const Material& material, const Light& light) {
  const double gain = material.translucency ? lobe_gain(*material.translucency) : 1.0;
  return material.albedo * light.color * light.translucency_scale * gain;
}

std::vector<double> fold_factors(const Scene& scene, const Material& mat) {
  std::vector<double> out;
  for (const Light& l : scene.lights) {
    const glm::dvec3 k = lobe_constant(mat, l);
    const double m = std::max({k.r, k.g, k.b});
    out.push_back(m > 4 ? m / 4 : 1.0);
  }
  return out;
}

VertexTerms vertex_terms(const Scene& s, const glm::dvec3& eye, size_t object,
                         const LobeTable* table) {
  const TriangleMesh& mesh = s.objects[object].mesh;
  const Material& mat = s.materials[static_cast<size_t>(s.objects[object].material)];
  const size_t n = mesh.positions.size();
  const size_t lights = s.lights.size();
  VertexTerms vt;
  vt.texcoord.assign(lights, std::vector<float>(n));
  vt.primary.assign(lights, std::vector<float>(n * 4));
  vt.secondary.assign(lights, std::vector<float>(n * 3));
  vt.thickness.assign(n * 4, 1.0f);
  vt.diffuse.assign(n * 4, 1.0f);
  const std::vector<double> fold = fold_factors(s, mat);
  const glm::dvec3 ambient = mat.albedo * s.ambient_light;
  // A map material (map_stage.h): T is the map's stage, a is in the table, K / g in the primary.
  const bool map = samples_thickness_map(mat);
  std::vector<glm::dvec3> map_primary(lights);
  for (size_t l = 0; l < lights && map; ++l) {
    const glm::dvec3 k = map_term_gain(mat, s.lights[l]);
    map_primary[l] = k / static_cast<double>(combiners::fit_scale(std::max({k.r, k.g, k.b})));
  }
  for (size_t v = 0; v < n; ++v) {
    const glm::dvec3& P = mesh.positions[v];
    const glm::dvec3 N = mesh.normals[v];  // unit or zero (model.md "no normal")
    const glm::dvec3 V = model::view_vector(s.camera, P - eye);
    const glm::dvec3 T = !mat.translucency ? glm::dvec3(0)
                         : map
                             ? glm::dvec3(1)
                             : model::thickness(*mat.translucency,
                                                mesh.has_colors() ? mesh.colors[v] : glm::dvec3(1));
    glm::dvec3 diffuse_sum = ambient;
    for (size_t l = 0; l < lights; ++l) {
      const Light& light = s.lights[l];
      const model::LightSample ls = model::sample_light(light, P, N);
      const double diffuse = ls.attenuation * std::max(glm::dot(N, ls.L), 0.0);
      diffuse_sum += mat.albedo * light.color * diffuse;
      if (!mat.translucency) continue;
      const Translucency& tr = *mat.translucency;
      const glm::dvec3 own =
          mat.albedo * light.color * (diffuse + (map ? 0.0 : ls.attenuation * tr.ambient) * T) +
          (l == 0 ? ambient : glm::dvec3(0));
      vt.texcoord[l][v] = static_cast<float>(
          table->coordinate(model::translucency_dot_unsaturated(V, ls.L, N, tr)));
      const glm::dvec3 prim = ls.attenuation * (map ? map_primary[l] : T * fold[l]);
      for (int c = 0; c < 3; ++c) {
        vt.primary[l][v * 4 + c] = static_cast<float>(prim[c]);
        vt.secondary[l][v * 3 + c] = static_cast<float>(own[c]);
      }
      vt.primary[l][v * 4 + 3] = 1.0f;
    }
    for (int c = 0; c < 3; ++c) {
      vt.thickness[v * 4 + c] = static_cast<float>(T[c]);
      vt.diffuse[v * 4 + c] = static_cast<float>(diffuse_sum[c]);
    }
  }
  return vt;
}

}  // namespace lt
