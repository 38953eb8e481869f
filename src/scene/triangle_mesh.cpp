#include "scene/triangle_mesh.h"

namespace lt {

void transform_to_world(TriangleMesh& mesh, const glm::dmat4& m) {
  const glm::dmat3 normal_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  for (auto& p : mesh.positions) p = glm::dvec3(m * glm::dvec4(p, 1.0));
  for (auto& n : mesh.normals) {
    const glm::dvec3 w = normal_matrix * n;
    const double len = glm::length(w);
    n = len > 0 ? w / len : glm::dvec3(0);
  }
}

std::size_t compute_area_weighted_normals(TriangleMesh& mesh) {
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0));
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::dvec3& a = mesh.positions[t.x];
    // |cross| is twice the triangle's area: the weight comes with the direction.
    const glm::dvec3 twice_area = glm::cross(mesh.positions[t.y] - a, mesh.positions[t.z] - a);
    for (int k = 0; k < 3; ++k) sum[t[k]] += twice_area;
  }
  mesh.normals.assign(sum.size(), glm::dvec3(0));
  std::size_t set = 0;
  for (std::size_t v = 0; v < sum.size(); ++v) {
    const double len = glm::length(sum[v]);
    if (len > 0) {
      mesh.normals[v] = sum[v] / len;
      ++set;
    }
  }
  return set;
}

}  // namespace lt
