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

// --- Meshes with texture coordinates (u, v per vertex; v = 0 is the bottom of an image, the
// OpenGL convention, see docs/input-files.md "Mesh UVs") ------------------------------------

// Sphere around the origin with equirectangular UVs: `rings` latitude bands (>= 2) and
// 2 * rings longitude segments. u = longitude / 2 pi (longitude 0 on +X, increasing towards -Z),
// v = (latitude + pi/2) / pi (0 at the south pole -Y, 1 at the north pole +Y). The seam column is
// duplicated (u = 0 and u = 1 at bit-identical positions); each pole is one vertex per segment,
// at u = the segment's middle, so no UV triangle is degenerate. Normals analytic (exactly +-Y at
// the poles).
PolyMesh uv_sphere(double radius, int rings);

// The Utah teapot, tessellated from Newell's 32 bicubic Bezier patches (mesh/teapot_data.cpp):
// each patch an n x n grid (n = `subdivisions`, 1..256) of two triangles per cell; where a
// patch edge collapses to a point (the lid knob's top, the bottom's centre) that row is one
// vertex per cell and one triangle per cell, as at a UV sphere's pole. Y up, the base at y = 0, the
// dataset's units (height 3.15, the spout's tip at x = 3.45). Every patch is one chart of a single
// UV atlas in [0, 1]^2 (mesh/uv_atlas.h): charts never overlap and are kept kTeapotGutterTexels
// apart at 1024 x 1024. Patches share no vertices (their charts differ), but the copies at one
// position have one normal: the patches' analytic normals (from the derivatives; next to a
// collapsed edge, from a sample just inside the patch), averaged over the copies. Outward-oriented;
// the teapot is not closed (the lid and the body's rim leave a gap, the spout is open, handle and
// spout pierce the body).
inline constexpr int kDefaultTeapotSubdivisions = 16;
// 16 texels at 1024 x 1024: a bake margin of up to 8 texels stays inside a chart's own gutter.
inline constexpr int kTeapotGutterTexels = 16;
PolyMesh teapot(int subdivisions);

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
  bool uvs = false;  // written with u, v
};
std::vector<NamedMesh> standard_set();

// How meshgen writes a mesh of the set: binary PLY with normals, and u, v when it has them.
OpenMesh::IO::Options write_options(const NamedMesh& named);

}  // namespace lt::meshgen
