// Meshes: read through OpenMesh (PLY, OFF, OBJ, STL, OM), validated, triangulated, with normals
// computed where the file has none. Positions stay in double until the GL upload.
#pragma once

#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Utils/color_cast.hh>
#include <cstddef>
#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

// OpenMesh 9.0's ExporterT instantiates color_cast<Vec4ui>(Color) for every mesh it writes and
// ships no caster from Vec3f (our Color), so writing a PolyMesh does not compile without this.
// It lives here, not in mesh.cpp, so that every translation unit sees the same specialisation.
namespace OpenMesh {
template <>
struct color_caster<Vec4ui, Vec3f> {
  using return_type = Vec4ui;
  static return_type cast(const Vec3f& c) {
    return Vec4ui(static_cast<unsigned int>(c[0] * 255.0f + 0.5f),
                  static_cast<unsigned int>(c[1] * 255.0f + 0.5f),
                  static_cast<unsigned int>(c[2] * 255.0f + 0.5f), 255u);
  }
};
}  // namespace OpenMesh

namespace lt {

// Double precision points and normals: bakes and the reference path work in double, and
// coordinates near 1e6 must survive a round trip. Colours are float rgb in [0, 1].
struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  using Color = OpenMesh::Vec3f;
  VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::Color);
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

// A mesh as read from a file, before triangulation: what the baker edits and writes back.
struct LoadedMesh {
  PolyMesh mesh;
  OpenMesh::IO::Options read_options;  // what the file had (normals, colours, ...)
  std::vector<std::string> warnings;   // e.g. "3 zero-length normals recomputed"
};

// Reads and validates. Throws InputError naming the file (and line where the reader knows it)
// for: missing or unreadable file, unknown format, empty mesh, no faces, NaN/Inf coordinates,
// face indices out of range. Missing, zero-length or non-finite normals are recomputed from the
// faces (area-weighted) and counted in `warnings`. Colours present in the file are kept.
// PLY is parsed by our own reader (exact double positions and float colours; OpenMesh 9.0 rounds
// both) and assembled with OpenMesh's importer; OBJ, OFF and STL are checked line by line before
// OpenMesh reads them, and OM is first read in a child process because a corrupt OM file can
// abort OpenMesh. Faces that repeat a vertex cannot exist in a halfedge mesh: they are dropped
// and counted in `warnings`. Thread-safe (OpenMesh's log streams are global, so reads and
// writes are serialised).
LoadedMesh read_mesh(const std::filesystem::path& path);

// Renderer-ready triangles.
struct TriangleMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;   // unit length, or zero where no normal exists (see model.md)
  std::vector<glm::dvec3> colors;    // empty when the file has no vertex colours
  std::vector<glm::uvec3> triangles;

  bool has_colors() const { return !colors.empty(); }
};

// Triangulates (fan per polygon, through OpenMesh) and flattens to arrays.
TriangleMesh to_triangle_mesh(const LoadedMesh& loaded);

// read_mesh + to_triangle_mesh.
TriangleMesh load_triangle_mesh(const std::filesystem::path& path);

// Writes a mesh by extension through OpenMesh, atomically (core/fs.h). `options` says which
// attributes to write (vertex colours, normals, binary, float colours). Throws InputError.
// PLY is written by our own writer with double x/y/z (OpenMesh 9.0 rounds positions to float,
// which a sphere near 1e6 does not survive); normals are float, colours float with ColorFloat
// and 8-bit otherwise. Other formats keep OpenMesh's own precision (OBJ/OFF/STL float; OM keeps
// double positions but stores colours in 8 bits).
void write_mesh(const std::filesystem::path& path, const PolyMesh& mesh,
                OpenMesh::IO::Options options);

// Area-weighted vertex normals (sum of the faces' Newell vectors, whose length is twice the face
// area) and unit face normals. A vertex whose faces are all degenerate, or that has no face, gets
// a zero normal (model.md: "no normal"). Returns how many vertices were left without a normal.
std::size_t compute_normals(PolyMesh& mesh);

}  // namespace lt
