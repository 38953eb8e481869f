// Renderer-ready triangles: plain arrays in double, what every path draws. mesh/mesh_io.h makes
// them from files; nothing here depends on the mesh library.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace lt {

struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // unit length, or zero where no normal exists (see model.md)
  std::vector<glm::dvec3> colors;   // empty when the file has no vertex colours
  std::vector<glm::uvec3> triangles;

  bool has_colors() const { return !colors.empty(); }
};

}  // namespace lt
