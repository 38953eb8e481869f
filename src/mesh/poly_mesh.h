// The editable mesh: OpenMesh's PolyMesh with double positions and normals, as read from a file
// (what the baker edits and writes back) and as meshgen makes it. Only mesh/ and bake/ see this
// type; the renderer takes the plain arrays of scene/triangle_mesh.h.
#pragma once

#include <OpenMesh/Core/IO/Options.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Utils/color_cast.hh>
#include <glm/glm.hpp>
#include <string>
#include <vector>

// OpenMesh 9.0's ExporterT instantiates color_cast<Vec4ui>(Color) for every mesh it writes and
// ships no caster from Vec3f (our Color), so writing a PolyMesh does not compile without this.
// It lives here, beside the traits, so that every translation unit sees the same specialisation.
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
// coordinates near 1e6 must survive a round trip. Colours are float rgb in [0, 1]. Texture
// coordinates are per vertex (a UV seam is a split vertex, as a GPU needs it), in double so that
// a PLY's double u, v survive; LoadedMesh::read_options says whether the mesh has them.
struct MeshTraits : public OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
  using Color = OpenMesh::Vec3f;
  using TexCoord2D = OpenMesh::Vec2d;
  VertexAttributes(OpenMesh::Attributes::Normal | OpenMesh::Attributes::Color |
                   OpenMesh::Attributes::TexCoord2D);
  FaceAttributes(OpenMesh::Attributes::Normal);
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

// A per-vertex value the renderer does not use (a PLY's quality, id, ...), kept so that a mesh
// written back (bake) carries everything it did not change: its PLY name and type, a value per
// vertex of the mesh.
struct ExtraVertexProperty {
  std::string name;
  std::string ply_type;  // as the file declared it: "float", "uchar", "int32", ...
  std::vector<double> values;
};

// A mesh as read from a file, before triangulation.
struct LoadedMesh {
  PolyMesh mesh;
  OpenMesh::IO::Options read_options;  // what the file had (normals, colours, VertexTexCoord)
  std::vector<ExtraVertexProperty> extra_vertex_properties;  // PLY only
  std::vector<std::string> warnings;  // e.g. "3 zero-length normals recomputed"
  // What any reader does unasked (normals computed for a file that has none): `bake`, which
  // writes them, says so; a render does not, on every frame of a user's CI.
  std::vector<std::string> notes;
  // Why the file's UVs were not kept, for a map material's error ("": kept, or the file had none).
  std::string uvs_dropped;
};

inline glm::dvec3 to_glm(const OpenMesh::Vec3d& v) {
  return {v[0], v[1], v[2]};
}
inline OpenMesh::Vec3d to_om(const glm::dvec3& v) {
  return {v.x, v.y, v.z};
}
inline glm::dvec2 to_glm(const OpenMesh::Vec2d& v) {
  return {v[0], v[1]};
}
inline OpenMesh::Vec2d to_om(const glm::dvec2& v) {
  return {v.x, v.y};
}

}  // namespace lt
