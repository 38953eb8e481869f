// Mesh density for the per-vertex paths (issue 29): the combiners and gx evaluate t per vertex
// and interpolate, which no variant fixes where t changes fastest (the silhouette). Refinement
// splits the edges whose midpoint the interpolation gets most wrong, conformingly (a triangle
// with 1, 2 or 3 split edges becomes 2, 3 or 4: no T-junction), the new vertex carrying the
// average of its edge's normals, baked thickness colours and UVs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "scene/scene.h"

namespace lt::advise {

// The error, in 8-bit LSB, of interpolating the shaded colour linearly along the edge a-b of an
// object of the scene, at its midpoint: |shade(midpoint) - (shade(a) + shade(b)) / 2|, largest
// channel, each clamped to [0, 1] as the 8-bit image is. An estimate of what per-vertex
// evaluation loses there, not a path's exact error.
double edge_midpoint_error_lsb(const Scene& scene, const SceneObject& object, unsigned a,
                               unsigned b);

// What refine_object remembers of one object between the steps of a refinement: the reference's
// colour at each vertex and the midpoint error of every edge estimated so far. Both stay true,
// since a step only appends vertices (an index keeps its vertex) and an edge's error depends
// on its two ends alone; without it every step would shade every edge's ends and midpoint
// again (each step's edges are mostly the last step's).
struct RefinementCache {
  std::vector<std::optional<glm::dvec3>> vertex_colour;
  std::unordered_map<std::uint64_t, double> edge_error;  // the lower index << 32 | the higher
};

// Splits every edge of `object` whose midpoint error is over `max_lsb` (all of them when
// max_lsb < 0: uniform subdivision, 1 triangle to 4) and the longest edge of every triangle
// with an edge to split (longest-edge bisection, so edges keep getting shorter). Returns the
// vertices added. `cache`, when given, must be the one this object's earlier steps used (or new).
std::size_t refine_object(const Scene& scene, SceneObject& object, double max_lsb,
                          RefinementCache* cache = nullptr);

}  // namespace lt::advise
