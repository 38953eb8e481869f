// Renderer-ready triangles: plain arrays in double, what every path draws. mesh/mesh_io.h makes
// them from mesh files and load/gltf/ from glTF primitives; nothing here depends on the mesh
// library.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

namespace lt {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // unit length, or zero where no normal exists (see model.md)
  std::vector<glm::dvec3> colors;   // empty when the file has no vertex colours
  std::vector<glm::dvec2> uvs;      // TEXCOORD_0 of a glTF primitive; empty when absent
  std::vector<glm::uvec3> triangles;

  bool has_colors() const { return !colors.empty(); }
};

// Object to world in double: positions by `m`, normals by its inverse transpose, renormalised
// (zero stays zero). What the reference shades and the GL paths upload camera-relative.
void transform_to_world(TriangleMesh& mesh, const glm::dmat4& m);

// Sets every vertex normal from the triangles around it, each weighted by its area (the sum of
// their unnormalised cross products), as the mesh reader does through OpenMesh; a vertex of
// degenerate triangles only keeps the zero normal of model.md. Returns how many were set.
std::size_t compute_area_weighted_normals(TriangleMesh& mesh);

}  // namespace lt
