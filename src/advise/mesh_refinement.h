// Mesh density for the per-vertex paths (issue 29): the combiners and gx evaluate t per vertex
// and interpolate, which no variant fixes where t changes fastest (the silhouette). Refinement
// splits the edges whose midpoint the interpolation gets most wrong, conformingly (a triangle
// with 1, 2 or 3 split edges becomes 2, 3 or 4: no T-junction), the new vertex carrying the
// average of its edge's normals, baked thickness colours and UVs.
#pragma once

#include <cstddef>

#include "scene/scene.h"

namespace lt::advise {

// The error, in 8-bit LSB, of interpolating the shaded colour linearly along the edge a-b of an
// object of the scene, at its midpoint: |shade(midpoint) - (shade(a) + shade(b)) / 2|, largest
// channel, each clamped to [0, 1] as the 8-bit image is. An estimate of what per-vertex
// evaluation loses there, not a path's exact error.
double edge_midpoint_error_lsb(const Scene& scene, const SceneObject& object, unsigned a,
                               unsigned b);

// Splits every edge of `object` whose midpoint error is over `max_lsb` (all of them when
// max_lsb < 0: uniform subdivision, 1 triangle to 4). Returns the vertices added.
std::size_t refine_object(const Scene& scene, SceneObject& object, double max_lsb);

}  // namespace lt::advise
