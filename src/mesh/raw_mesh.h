// What a format's reader hands on: the file as plain arrays (RawMesh), or what a check learnt
// about a file that OpenMesh then reads (FileFacts); and the one way arrays become a PolyMesh.
#pragma once

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "mesh/poly_mesh.h"

namespace lt::meshio {

// What the format checks learn about a file, used once OpenMesh has read it.
struct FileFacts {
  std::size_t vertices = 0;        // vertex records in the file; 0 when the check cannot tell
  std::size_t repeated_faces = 0;  // faces naming a vertex twice (OpenMesh drops or shrinks them)
  std::vector<char> normal_given;  // per vertex: the file gave it a normal (OBJ: via a face)
  std::vector<glm::vec3> colors;   // exact colours when we parsed them ourselves
  bool has_colors = false;         // `colors` is valid for every vertex
  bool partial_colors = false;     // some vertices had colours and others not: dropped
  bool colors_checked = false;     // our pass decides about colours, not OpenMesh's options
  // OBJ: the first face line whose corners name `vt` where earlier corners did not, or the
  // reverse (0: none). Such a file's UVs are dropped with a warning, not refused: assimp and
  // tinyobjloader read it (tinyobjloader gives such a corner texcoord_index -1).
  std::size_t uv_mix_line = 0;
  // OFF: faces whose colours (values after the indices) were dropped, and the text OpenMesh
  // reads instead of the file ("": the file as it is), both from check_off.
  std::size_t face_colours_dropped = 0;
  std::string rewritten;

  // A text check's colours, one per vertex record (zero where the record had none), `colored`
  // of them from the file: kept when every vertex has one, dropped (with a warning later) when
  // only some have. Call after setting `vertices`.
  void take_parsed_colors(std::vector<glm::vec3> parsed, std::size_t colored);
};

// A mesh as plain arrays (a parsed PLY file, or what an OM file's halfedges describe), before
// it becomes a PolyMesh.
struct RawMesh {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // empty when the file has none
  std::vector<glm::vec3> colors;    // empty when the file has none
  bool float_colors = false;
  std::vector<glm::dvec2> uvs;  // empty when the file has none
  std::vector<std::uint32_t> face_offsets{0};
  std::vector<std::uint32_t> face_indices;
  bool binary = false;
  std::vector<ExtraVertexProperty> extras;  // per file vertex
  std::vector<std::string> warnings;        // what the reader accepted but the user should know
};

// Builds the mesh from arrays through OpenMesh's importer, so that the connectivity is whatever
// add_face makes of the faces (consistent by construction), whatever the file said. Returns,
// per mesh vertex, the RawMesh vertex it came from (itself, or the corner a non-manifold copy
// copied).
std::vector<std::uint32_t> build_mesh(const RawMesh& raw, LoadedMesh& loaded, FileFacts& facts);

}  // namespace lt::meshio
