// Procedural meshes. Each generator first builds plain arrays (mesh/mesh_builder.h) and converts
// to a PolyMesh once at the end. The UV sphere and the teapot have files of their own.
#include "mesh/meshgen.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>

#include "core/error.h"
#include "mesh/mesh_builder.h"
#include "mesh/normals.h"

namespace lt::meshgen {

namespace {

Geometry icosphere_geometry(double radius, int subdivisions) {
  LT_CHECK(subdivisions >= 0 && subdivisions <= 8, "icosphere subdivisions out of range");
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  const glm::dvec3 corners[12] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                  {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                  {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  // Counter-clockwise seen from outside.
  std::vector<std::array<int, 3>> faces = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  std::vector<glm::dvec3> dirs;
  for (const auto& c : corners) dirs.push_back(glm::normalize(c));
  for (int s = 0; s < subdivisions; ++s) {
    // One new vertex per edge, shared by the edge's two faces.
    std::map<std::pair<int, int>, int> midpoints;
    auto midpoint = [&](int a, int b) {
      auto key = std::minmax(a, b);
      auto it = midpoints.find(key);
      if (it != midpoints.end()) return it->second;
      dirs.push_back(
          glm::normalize(dirs[static_cast<std::size_t>(a)] + dirs[static_cast<std::size_t>(b)]));
      const int m = static_cast<int>(dirs.size()) - 1;
      midpoints.emplace(key, m);
      return m;
    };
    std::vector<std::array<int, 3>> next;
    next.reserve(4 * faces.size());
    for (const auto& f : faces) {
      const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
      next.push_back({f[0], ab, ca});
      next.push_back({f[1], bc, ab});
      next.push_back({f[2], ca, bc});
      next.push_back({ab, bc, ca});
    }
    faces = std::move(next);
  }
  Geometry g;
  for (const auto& d : dirs) g.add(radius * d, d);
  g.triangles = std::move(faces);
  return g;
}

// --- blob -----------------------------------------------------------------------------------

// A lobe is a bump of the radius, Gaussian across the sphere: narrow along `thin` and wider
// along `wide`, so a tall lobe becomes an ear or a fin whose thickness falls to zero at its tip.
struct Lobe {
  glm::dvec3 axis, thin, wide;
  double height, thin_width, wide_width;
};

Lobe make_lobe(glm::dvec3 axis, glm::dvec3 thin_hint, double height, double thin_width,
               double wide_width) {
  axis = glm::normalize(axis);
  const glm::dvec3 thin = glm::normalize(thin_hint - glm::dot(thin_hint, axis) * axis);
  return {axis, thin, glm::cross(axis, thin), height, thin_width, wide_width};
}

double blob_radius(const glm::dvec3& d) {
  static const Lobe lobes[] = {
      make_lobe({0.35, 1.0, 0.15}, {0, 0, 1}, 0.75, 0.07, 0.20),    // left ear, thin front-back
      make_lobe({-0.35, 1.0, -0.10}, {0, 0, 1}, 0.65, 0.07, 0.17),  // right ear
      make_lobe({1.0, -0.25, 0.35}, {0, 1, 0}, 0.45, 0.06, 0.22),   // horizontal fin
      make_lobe({-0.5, -0.6, 0.6}, {1, 0, 0}, 0.30, 0.30, 0.30),    // a broad bulge
  };
  // Low-frequency waves: the body's thickness varies smoothly as well.
  double r = 1.0 + 0.10 * std::sin(2.1 * d.x + 0.4) * std::cos(1.7 * d.y - 0.3) +
             0.07 * std::sin(2.9 * d.z + 1.3 * d.x + 0.9) + 0.05 * std::cos(3.3 * d.y + 2.2 * d.z);
  for (const auto& l : lobes) {
    const double c = glm::dot(d, l.axis);
    if (c <= 0.0) continue;
    const double a = glm::dot(d, l.thin) / l.thin_width, b = glm::dot(d, l.wide) / l.wide_width;
    // c^2 fades the lobe out smoothly before the far hemisphere.
    r += l.height * c * c * std::exp(-0.5 * (a * a + b * b));
  }
  return r;
}

}  // namespace

PolyMesh icosphere(double radius, int subdivisions) {
  return to_mesh(icosphere_geometry(radius, subdivisions));
}

PolyMesh box(const glm::dvec3& half_extents, int n) {
  LT_CHECK(n >= 1, "box needs at least one cell per face");
  Geometry g;
  // The same expression for the same (axis, i) on every face, so that edges shared by two
  // faces land on bit-identical positions (the box is closed in space).
  auto coord = [&](int axis, int i) { return half_extents[axis] * (-1.0 + 2.0 * i / n); };
  for (int axis = 0; axis < 3; ++axis) {
    for (int sign : {1, -1}) {
      // (u, v, normal) right-handed, so quads listed in (u, v) order face outward.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (sign < 0) std::swap(u, v);
      glm::dvec3 normal(0.0);
      normal[axis] = sign;
      const int base = static_cast<int>(g.positions.size());
      for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
          glm::dvec3 p(0.0);
          p[axis] = sign * half_extents[axis];
          p[u] = coord(u, i);
          p[v] = coord(v, j);
          g.add(p, normal);
        }
      }
      auto at = [&](int i, int j) { return base + j * (n + 1) + i; };
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i)
          add_quad(g, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
      }
    }
  }
  return to_mesh(g);
}

PolyMesh torus(double major_radius, double minor_radius, int major_segments, int minor_segments) {
  LT_CHECK(major_segments >= 3 && minor_segments >= 3, "torus needs at least 3 segments each way");
  Geometry g;
  const double two_pi = 2.0 * std::numbers::pi;
  for (int i = 0; i < major_segments; ++i) {
    const double u = two_pi * i / major_segments;
    const glm::dvec3 radial(std::cos(u), 0.0, std::sin(u));
    for (int j = 0; j < minor_segments; ++j) {
      const double v = two_pi * j / minor_segments;
      const glm::dvec3 normal = std::cos(v) * radial + glm::dvec3(0.0, std::sin(v), 0.0);
      g.add(major_radius * radial + minor_radius * normal, normal);
    }
  }
  auto at = [&](int i, int j) {
    return (i % major_segments) * minor_segments + (j % minor_segments);
  };
  // Walking the tube (j) before the ring (i) makes the quads face outward.
  for (int i = 0; i < major_segments; ++i) {
    for (int j = 0; j < minor_segments; ++j)
      add_quad(g, at(i, j), at(i, j + 1), at(i + 1, j + 1), at(i + 1, j));
  }
  return to_mesh(g);
}

PolyMesh quad(double half_size, int n) {
  LT_CHECK(n >= 1, "quad needs at least one cell");
  Geometry g;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      g.add({half_size * (-1.0 + 2.0 * i / n), half_size * (-1.0 + 2.0 * j / n), 0.0}, {0, 0, 1});
    }
  }
  auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) add_quad(g, at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
  }
  return to_mesh(g);
}

PolyMesh blob(int subdivisions) {
  Geometry g = icosphere_geometry(1.0, subdivisions);
  // Radial displacement keeps the surface star-shaped around the origin, so it cannot fold or
  // intersect itself, and every triangle keeps its outward orientation (its tetrahedron with
  // the origin only changes size; the squash, scale and shift below keep that). The squash
  // makes the body thinner front to back.
  const glm::dvec3 squash(1.0, 0.9, 0.8);
  for (auto& p : g.positions) p = squash * (blob_radius(p) * p);
  // The ears make it lopsided: centre its bounding box on the origin and make the largest
  // half-extent 1.2, so that it frames like the unit-radius meshes.
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const auto& p : g.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi), half = 0.5 * (hi - lo);
  const double scale = 1.2 / std::max({half.x, half.y, half.z});
  for (auto& p : g.positions) p = scale * (p - centre);
  PolyMesh mesh = to_mesh(g);
  compute_normals(mesh);  // smooth, from the displaced surface
  return mesh;
}

PolyMesh degenerate_sphere(int subdivisions, int count) {
  Geometry g = icosphere_geometry(1.0, subdivisions);
  // Directed edge -> triangle, to find the neighbour across an edge.
  std::map<std::pair<int, int>, std::size_t> owner;
  for (std::size_t t = 0; t < g.triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) owner[{g.triangles[t][k], g.triangles[t][(k + 1) % 3]}] = t;
  }
  std::vector<char> used(g.triangles.size(), 0);
  const std::size_t n_before = g.triangles.size();
  const std::size_t step =
      std::max<std::size_t>(1, n_before / static_cast<std::size_t>(2 * count + 1));
  int made = 0;
  for (std::size_t t = step / 2; t < n_before && made < count; t += step) {
    const auto tri = g.triangles[t];
    const int a = tri[0], b = tri[1], c = tri[2];
    const std::size_t other = owner.at({b, a});
    if (used[t] || used[other]) continue;
    used[t] = used[other] = 1;
    // Split edge a->b of (a, b, c) at m into (a, m, c) and (m, b, c), and close the gap
    // against the untouched neighbour (b, a, d) with (a, b, m): zero area, every edge still
    // shared by exactly two faces.
    const bool collinear = made % 2 == 0;
    const glm::dvec3 pa = g.positions[static_cast<std::size_t>(a)];
    const glm::dvec3 pb = g.positions[static_cast<std::size_t>(b)];
    const glm::dvec3 pm = collinear ? 0.5 * (pa + pb) : pa;  // else coincident with a
    const int m = g.add(pm, glm::normalize(collinear ? pa + pb : pa));
    g.triangles[t] = {a, m, c};
    g.triangles.push_back({m, b, c});
    g.triangles.push_back({a, b, m});
    ++made;
  }
  LT_CHECK(made == count, "degenerate_sphere: too few edges to split on this sphere");
  return to_mesh(g);
}

PolyMesh zero_normal_sphere(int subdivisions) {
  Geometry g = icosphere_geometry(1.0, subdivisions);
  for (std::size_t i = 3; i < g.normals.size(); i += 7) g.normals[i] = glm::dvec3(0.0);
  return to_mesh(g);
}

PolyMesh nonunit_normal_sphere(int subdivisions) {
  Geometry g = icosphere_geometry(1.0, subdivisions);
  const double scales[] = {0.5, 2.0, 10.0, 1e-3, 3.7};
  for (std::size_t i = 0; i < g.normals.size(); ++i) g.normals[i] *= scales[i % 5];
  return to_mesh(g);
}

void translate(PolyMesh& mesh, const glm::dvec3& offset) {
  for (auto vh : mesh.vertices()) mesh.point(vh) += PolyMesh::Point(offset.x, offset.y, offset.z);
}

std::vector<NamedMesh> standard_set() {
  std::vector<NamedMesh> set;
  for (int s = 1; s <= 5; ++s)
    set.push_back({"sphere_s" + std::to_string(s) + ".ply", icosphere(1.0, s)});
  set.push_back({"cube.ply", box({1.0, 1.0, 1.0}, 8)});
  set.push_back({"torus.ply", torus(0.7, 0.3, 96, 48)});
  set.push_back({"slab.ply", box({1.0, 1.0, 0.05}, 8)});
  set.push_back({"block.ply", box({0.5, 1.0, 0.75}, 8)});
  set.push_back({"quad.ply", quad(1.0, 4)});
  set.push_back({"blob.ply", blob(5)});
  set.push_back({"hard/degenerate.ply", degenerate_sphere(3, 24)});
  set.push_back({"hard/zero_normals.ply", zero_normal_sphere(3)});
  set.push_back({"hard/nonunit_normals.ply", nonunit_normal_sphere(3)});
  PolyMesh far = icosphere(1.0, 4);
  translate(far, glm::dvec3(1e6));
  set.push_back({"hard/far_1e6.ply", std::move(far)});
  set.push_back({"hard/tiny_1e-6.ply", icosphere(1e-6, 4)});
  set.push_back({"uvsphere.ply", uv_sphere(1.0, 32), true});
  set.push_back({"teapot.ply", teapot(kDefaultTeapotSubdivisions), true});
  return set;
}

OpenMesh::IO::Options write_options(const NamedMesh& named) {
  using OpenMesh::IO::Options;
  Options options(Options::Binary | Options::VertexNormal);
  if (named.uvs) options += Options::VertexTexCoord;
  return options;
}

}  // namespace lt::meshgen
