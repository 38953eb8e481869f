// The combiners path's per-vertex work, on the CPU in double each frame, as a fixed-function
// engine would do it: t, attenuation, diffuse and thickness per vertex, streamed as vertex
// arrays.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "paths/combiners/lobe_table.h"
#include "scene/scene.h"

namespace lt {

// Per-vertex inputs of one object for one frame.
struct VertexTerms {
  // Per light: the lobe table's coordinate of the unsaturated t (the texture's CLAMP_TO_EDGE
  // saturates per pixel, after interpolation, as the per-pixel model does), att * T * fold (rgba),
  // and the
  // light's diffuse and ambient part albedo * color * att * (diffuse + a*T) (rgb; pass 0 also
  // carries albedo * ambient_light).
  std::vector<std::vector<float>> texcoord, primary, secondary;
  std::vector<float> thickness;  // rgba: T, the primary colour of a lobe=cube pass
  std::vector<float> diffuse;    // rgba: albedo * (ambient + sum of color * att * diffuse), the
                                 // whole term of a material without translucency
};

// K = albedo * color * s * gain (lobe_table.h: the table holds the lobe / gain): what the lobe
// read from the table is multiplied by, as lobe_vertex.comb's constant colour.
glm::dvec3 lobe_constant(const Material& material, const Light& light);

// K reaches the combiner as a constant (clamped to [0, 1]) times a scale of at most 4. Where K
// exceeds 4 the excess f = K/4 moves into the primary colour (att*T*f), which is exact while
// att*T*f <= 1. One factor per light.
std::vector<double> fold_factors(const Scene& scene, const Material& material);

// `eye`: what positions are relative to (camera-relative rendering); `table`: the material's lobe
// table, whose coordinate t becomes (null for a material without translucency).
VertexTerms vertex_terms(const Scene& scene, const glm::dvec3& eye, size_t object,
                         const LobeTable* table);

}  // namespace lt
