#include "mesh/triangulate.h"

#include <cmath>
#include <numeric>

namespace lt {

namespace {

// Newell's normal of the polygon (length twice the area), as a fan of cross products from the
// first corner so that coordinates near 1e6 keep the polygon's own size.
glm::dvec3 area_vector(const std::vector<glm::dvec3>& c) {
  glm::dvec3 sum(0.0);
  for (std::size_t k = 2; k < c.size(); ++k) sum += glm::cross(c[k - 1] - c[0], c[k] - c[0]);
  return sum;
}

void fan(std::size_t n, std::vector<std::array<std::size_t, 3>>& out) {
  for (std::size_t k = 1; k + 1 < n; ++k) out.push_back({0, k, k + 1});
}

// Twice the signed area of the 2D triangle (a, b, c): > 0 counter-clockwise.
double orient(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool inside_triangle(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b,
                     const glm::dvec2& c) {
  return orient(a, b, p) >= 0 && orient(b, c, p) >= 0 && orient(c, a, p) >= 0;
}

}  // namespace

void triangulate_polygon(const std::vector<glm::dvec3>& corners,
                         std::vector<std::array<std::size_t, 3>>& out) {
  const std::size_t n = corners.size();
  if (n < 3) return;
  const glm::dvec3 normal = area_vector(corners);
  const double length = glm::length(normal);
  if (n == 3 || !(length > 0.0) || !std::isfinite(length)) return fan(n, out);

  // Project onto the polygon's plane, counter-clockwise seen along the normal.
  const glm::dvec3 nz = normal / length;
  const glm::dvec3 helper = std::fabs(nz.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  const glm::dvec3 ax = glm::normalize(glm::cross(helper, nz));
  const glm::dvec3 ay = glm::cross(nz, ax);
  std::vector<glm::dvec2> p(n);
  for (std::size_t k = 0; k < n; ++k) {
    const glm::dvec3 d = corners[k] - corners[0];
    p[k] = {glm::dot(d, ax), glm::dot(d, ay)};
  }
  bool convex = true;
  for (std::size_t k = 0; k < n && convex; ++k)
    convex = orient(p[k], p[(k + 1) % n], p[(k + 2) % n]) >= 0;
  if (convex) return fan(n, out);

  // Ear clipping: a corner whose triangle turns left and holds no other remaining corner is
  // cut off, until three are left. O(n^3) at worst, and OBJ polygons have a handful of corners.
  std::vector<std::size_t> left(n);
  std::iota(left.begin(), left.end(), std::size_t{0});
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t i = 0; i < left.size() && !clipped; ++i) {
      const std::size_t a = left[(i + left.size() - 1) % left.size()], b = left[i],
                        c = left[(i + 1) % left.size()];
      if (orient(p[a], p[b], p[c]) <= 0) continue;  // reflex or flat: not an ear
      bool empty = true;
      for (std::size_t other : left) {
        if (other != a && other != b && other != c && inside_triangle(p[other], p[a], p[b], p[c])) {
          empty = false;
          break;
        }
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
      clipped = true;
    }
    // A self-intersecting polygon can run out of ears: the rest is fanned, as before.
    if (!clipped) break;
  }
  for (std::size_t k = 1; k + 1 < left.size(); ++k) out.push_back({left[0], left[k], left[k + 1]});
}

std::vector<glm::uvec3> triangulate_faces(const PolyMesh& mesh) {
  std::vector<glm::uvec3> out;
  out.reserve(mesh.n_faces());
  std::vector<unsigned int> corners;
  std::vector<glm::dvec3> points;
  std::vector<std::array<std::size_t, 3>> triangles;
  for (auto fh : mesh.faces()) {
    corners.clear();
    points.clear();
    triangles.clear();
    for (auto vh : mesh.fv_range(fh)) {
      corners.push_back(static_cast<unsigned int>(vh.idx()));
      points.push_back(to_glm(mesh.point(vh)));
    }
    triangulate_polygon(points, triangles);
    for (const auto& t : triangles) out.emplace_back(corners[t[0]], corners[t[1]], corners[t[2]]);
  }
  return out;
}

}  // namespace lt
