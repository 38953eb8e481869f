// meshgen::uv_sphere: the latitude-longitude sphere whose UVs are the equirectangular map.
#include <cmath>
#include <numbers>

#include "core/error.h"
#include "mesh/mesh_builder.h"
#include "mesh/meshgen.h"

namespace lt::meshgen {

PolyMesh uv_sphere(double radius, int rings) {
  LT_CHECK(rings >= 2 && rings <= 4096, "uv sphere rings out of range");
  const int segments = 2 * rings;
  const double pi = std::numbers::pi;
  Geometry g;
  // The unit direction at (longitude, latitude); the seam column reuses column 0's angle so
  // that u = 0 and u = 1 sit at bit-identical positions.
  auto direction = [&](int column, int ring) {
    const double lon = 2.0 * pi * (column % segments) / segments;
    const double lat = -pi / 2 + pi * ring / rings;
    return glm::dvec3(std::cos(lat) * std::cos(lon), std::sin(lat), -std::cos(lat) * std::sin(lon));
  };
  // South pole: one vertex per segment, at the segment's middle u.
  const int south = 0;
  for (int j = 0; j < segments; ++j) {
    g.add({0.0, -radius, 0.0}, {0.0, -1.0, 0.0}, {(j + 0.5) / segments, 0.0});
  }
  // Rings 1 .. rings-1, segments + 1 columns each (column `segments` is the seam copy).
  const int first_ring = static_cast<int>(g.positions.size());
  auto ring_vertex = [&](int ring, int column) {
    return first_ring + (ring - 1) * (segments + 1) + column;
  };
  for (int i = 1; i < rings; ++i) {
    for (int j = 0; j <= segments; ++j) {
      const glm::dvec3 d = direction(j, i);
      g.add(radius * d, d, {static_cast<double>(j) / segments, static_cast<double>(i) / rings});
    }
  }
  const int north = static_cast<int>(g.positions.size());
  for (int j = 0; j < segments; ++j) {
    g.add({0.0, radius, 0.0}, {0.0, 1.0, 0.0}, {(j + 0.5) / segments, 1.0});
  }
  // (u, v) is right-handed seen from outside (du x dv points outward), so triangles
  // counter-clockwise in UV are counter-clockwise from outside.
  for (int j = 0; j < segments; ++j) {
    g.triangles.push_back({south + j, ring_vertex(1, j + 1), ring_vertex(1, j)});
    for (int i = 1; i + 1 < rings; ++i) {
      add_quad(g, ring_vertex(i, j), ring_vertex(i, j + 1), ring_vertex(i + 1, j + 1),
               ring_vertex(i + 1, j));
    }
    g.triangles.push_back({ring_vertex(rings - 1, j), ring_vertex(rings - 1, j + 1), north + j});
  }
  return to_mesh(g);
}

}  // namespace lt::meshgen
