// Vertex and face normals of a PolyMesh, computed in double.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

#include "mesh/poly_mesh.h"

namespace lt {

// Area-weighted vertex normals (sum of the faces' Newell vectors, whose length is twice the face
// area) and unit face normals. A vertex whose faces are all degenerate, or that has no face, gets
// a zero normal (model.md: "no normal"). Returns how many vertices were left without a normal.
std::size_t compute_normals(PolyMesh& mesh);

namespace meshio {

bool is_finite(const glm::dvec3& v);
bool is_finite(const glm::dvec2& v);

// Normalises without overflow or underflow (a normal of length 1e-200 still has a direction);
// returns zero for zero and non-finite input.
glm::dvec3 safe_normalize(glm::dvec3 v);

// Recomputes the vertex normals where `keep` is 0 (all when `keep` is empty) and every face
// normal; returns how many recomputed vertices are left without a normal.
std::size_t recompute_normals(PolyMesh& mesh, const std::vector<char>& keep);

}  // namespace meshio
}  // namespace lt
