// What every generator of mesh/meshgen.h builds first: plain arrays (positions, normals, optional
// UVs, triangles), because splitting edges and displacing vertices is simpler there, converted to
// a PolyMesh once at the end.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <vector>

#include "mesh/poly_mesh.h"

namespace lt::meshgen {

struct Geometry {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<glm::dvec2> uvs;  // empty, or one per vertex
  std::vector<std::array<int, 3>> triangles;

  int add(const glm::dvec3& p, const glm::dvec3& n) {
    positions.push_back(p);
    normals.push_back(n);
    return static_cast<int>(positions.size()) - 1;
  }
  int add(const glm::dvec3& p, const glm::dvec3& n, const glm::dvec2& uv) {
    uvs.push_back(uv);
    return add(p, n);
  }
};

// Vertex normals as given (compute_normals fills the face normals; its vertex normals are then
// replaced), colours zero, texture coordinates when `g.uvs` has them.
PolyMesh to_mesh(const Geometry& g);

// Quad (a, b, c, d), counter-clockwise seen from its front, as two triangles.
void add_quad(Geometry& g, int a, int b, int c, int d);

}  // namespace lt::meshgen
