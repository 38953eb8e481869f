// Procedural meshes: everything in meshes/ is made by `ltrender meshgen` from these, so the
// repository holds no copied models. All are closed, consistently outward-oriented triangle
// meshes unless the name says otherwise (quad is open).
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "mesh/poly_mesh.h"

namespace lt::meshgen {

// Geodesic sphere: an icosahedron subdivided `subdivisions` times (20 * 4^s faces).
PolyMesh icosphere(double radius, int subdivisions);
// Axis-aligned box centred at the origin, each face split into n x n quads (then triangles).
// The six faces do not share vertices, so each keeps its flat normal and the edges stay crisp:
// the box is closed in space (each edge lies on two faces, at bit-identical positions) but its
// faces are six separate pieces of connectivity.
PolyMesh box(const glm::dvec3& half_extents, int n);
// Torus around +Y: major radius R, tube radius r.
PolyMesh torus(double major_radius, double minor_radius, int major_segments, int minor_segments);
// Open square in the XY plane facing +Z, side 2*half_size, n x n cells.
PolyMesh quad(double half_size, int n);
// Organic shape: a sphere with smooth, low-frequency displacement and a few thin lobes, so that
// local thickness varies a lot over its surface (what the translucency term is about).
PolyMesh blob(int subdivisions);

// Every generator writes explicit unit vertex normals (analytic for sphere, torus, box and quad;
// area-weighted for the blob), unit face normals and zero colours, and is deterministic: the
// same arguments give the same file, byte for byte.

// --- The hard cases of model.md, as meshes -------------------------------------------------

// Icosphere with `count` edges split by zero-area triangles that keep the mesh closed: half
// of them collinear (a vertex at an edge's midpoint), half with two coincident corners.
PolyMesh degenerate_sphere(int subdivisions, int count);
// Icosphere whose file normals are zero on every 7th vertex (the rest analytic).
PolyMesh zero_normal_sphere(int subdivisions);
// Icosphere whose normals are scaled by 0.5, 2, 10, 1e-3 and 3.7 in turn.
PolyMesh nonunit_normal_sphere(int subdivisions);
// Moves every vertex (normals unchanged).
void translate(PolyMesh& mesh, const glm::dvec3& offset);

// What `ltrender meshgen OUTDIR` writes: paths relative to OUTDIR ("sphere_s1.ply",
// "hard/degenerate.ply", ...), meshes ready to be written as binary PLY with normals.
struct NamedMesh {
  std::string path;
  PolyMesh mesh;
};
std::vector<NamedMesh> standard_set();

}  // namespace lt::meshgen
