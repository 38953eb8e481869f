// Polygons into triangles. OpenMesh's PolyConnectivity::triangulate splits every face as a fan
// from one corner, which is right for convex polygons only: a concave one (assimp's
// concave_polygon.obj) gets triangles outside the polygon that overlap with the opposite
// winding. Convex polygons are fanned from their first corner (what OpenMesh and every GL
// loader do, and what the goldens were rendered with); the others are ear-clipped.
#pragma once

#include <array>
#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "mesh/poly_mesh.h"

namespace lt {

// Appends the triangles of the polygon `corners` (in order, roughly planar) to `out`, as
// indices into `corners`, keeping the polygon's winding. A degenerate polygon (no area) is
// fanned: its triangles are degenerate too, and the renderer handles those (model.md).
void triangulate_polygon(const std::vector<glm::dvec3>& corners,
                         std::vector<std::array<std::size_t, 3>>& out);

// Every face of `mesh` so, as vertex-handle indices: what the renderer draws and the baker casts
// against.
std::vector<glm::uvec3> triangulate_faces(const PolyMesh& mesh);

}  // namespace lt
