// Mesh files: read through OpenMesh (PLY, OFF, OBJ, STL, OM), validated, triangulated, with
// normals computed where the file has none; written atomically. Positions stay in double until
// the GL upload. One file per format lives in mesh/formats/.
#pragma once

#include <filesystem>

#include "mesh/poly_mesh.h"
#include "scene/triangle_mesh.h"

namespace lt {

// Reads and validates. Throws InputError naming the file (and line where the reader knows it)
// for: missing or unreadable file, unknown format, empty mesh, no faces, NaN/Inf coordinates,
// face indices out of range. Missing, zero-length or non-finite normals are recomputed from the
// faces (area-weighted) and counted in `warnings`. Colours present in the file are kept, and so
// are texture coordinates (read_options has VertexTexCoord): PLY u/v, s/t or
// texture_u/texture_v (float or double), OBJ vt (per face corner; a position with several is
// split, see uv_seams.h), OFF st, OM texcoords; non-finite ones, or a vt index out of range, are
// an InputError naming the line.
// PLY is parsed by our own reader (exact double positions and float colours; OpenMesh 9.0 rounds
// both) and assembled with OpenMesh's importer; OBJ, OFF and STL are checked line by line before
// OpenMesh reads them, and OM is first read in a child process because a corrupt OM file can
// abort OpenMesh. Faces that repeat a vertex cannot exist in a halfedge mesh: they are dropped
// and counted in `warnings`. Thread-safe (OpenMesh's log streams are global, so reads and
// writes are serialised).
LoadedMesh read_mesh(const std::filesystem::path& path);

// Triangulates (fan per polygon) and flattens to arrays.
TriangleMesh to_triangle_mesh(const LoadedMesh& loaded);

// read_mesh + to_triangle_mesh.
TriangleMesh load_triangle_mesh(const std::filesystem::path& path);

// Writes a mesh by extension, atomically (core/fs.h). `options` says which attributes to write
// (vertex colours, normals, binary, float colours). Throws InputError.
// PLY is written by our own writer with double x/y/z (OpenMesh 9.0 rounds positions to float,
// which a sphere near 1e6 does not survive); normals are float, colours float with ColorFloat
// and 8-bit otherwise; texture coordinates (Options::VertexTexCoord) as u, v. Other formats keep
// OpenMesh's own precision (OBJ/OFF/STL float; OM keeps double positions but stores colours in
// 8 bits). `extras` (a PLY's quality, ... from read_mesh)
// are written after the attributes; only PLY can hold them, so another format with extras is an
// InputError naming them.
void write_mesh(const std::filesystem::path& path, const PolyMesh& mesh,
                OpenMesh::IO::Options options, const std::vector<ExtraVertexProperty>& extras = {});

// Writes a mesh the renderer holds (a refined one: advise -o) as binary PLY, atomically, for
// load_triangle_mesh to read back: double positions, float normals, float colours (the baked
// thickness; 8 bits would move it) when it has colours, UVs when it has them, its triangles as
// faces in order. Throws InputError naming `path` when a triangle cannot be a face of OpenMesh's
// halfedge mesh (a non-manifold edge): the file would lose it.
void write_triangle_mesh(const std::filesystem::path& path, const TriangleMesh& mesh);

}  // namespace lt
