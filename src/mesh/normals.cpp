#include "mesh/normals.h"

#include <algorithm>
#include <cmath>

namespace lt {
namespace meshio {

bool is_finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool is_finite(const glm::dvec2& v) {
  return std::isfinite(v.x) && std::isfinite(v.y);
}

glm::dvec3 safe_normalize(glm::dvec3 v) {
  if (!is_finite(v)) return glm::dvec3(0.0);
  double m = std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
  if (!(m > 0.0)) return glm::dvec3(0.0);
  v /= m;
  return v / glm::length(v);
}

namespace {

// Twice the area times the unit normal: Newell's sum as a fan of cross products relative to the
// first corner, so that coordinates near 1e6 do not cancel away the face's own size.
glm::dvec3 face_area_vector(const PolyMesh& mesh, OpenMesh::FaceHandle fh) {
  glm::dvec3 sum(0.0), first(0.0), prev(0.0);
  int k = 0;
  for (auto vh : mesh.fv_range(fh)) {
    const glm::dvec3 p = to_glm(mesh.point(vh));
    if (k == 0) {
      first = p;
    } else if (k >= 2) {
      sum += glm::cross(prev - first, p - first);
    }
    prev = p;
    ++k;
  }
  return sum;
}

}  // namespace

std::size_t recompute_normals(PolyMesh& mesh, const std::vector<char>& keep) {
  std::vector<glm::dvec3> area(mesh.n_faces());
  for (auto fh : mesh.faces()) {
    area[static_cast<std::size_t>(fh.idx())] = face_area_vector(mesh, fh);
    mesh.set_normal(fh, to_om(safe_normalize(area[static_cast<std::size_t>(fh.idx())])));
  }
  std::size_t without = 0;
  for (auto vh : mesh.vertices()) {
    if (!keep.empty() && keep[static_cast<std::size_t>(vh.idx())]) continue;
    // Area vectors of a 1e-6 mesh are ~1e-12 long; safe_normalize rescales before it
    // normalises, so their sum keeps its direction.
    glm::dvec3 sum(0.0);
    for (auto fh : mesh.vf_range(vh)) sum += area[static_cast<std::size_t>(fh.idx())];
    const glm::dvec3 n = safe_normalize(sum);
    if (n == glm::dvec3(0.0)) ++without;
    mesh.set_normal(vh, to_om(n));
  }
  return without;
}

}  // namespace meshio

std::size_t compute_normals(PolyMesh& mesh) {
  return meshio::recompute_normals(mesh, {});
}

}  // namespace lt
