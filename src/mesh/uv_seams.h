// UV seams: an OBJ gives texture coordinates per face corner (`f v/vt`), so one position can
// carry different UVs in the faces around it. The renderer's arrays and a PLY hold one UV per
// vertex, as a GPU does, so such a vertex is split: one copy per distinct UV, each keeping the
// position, normal and colour of the original.
#pragma once

#include <cstddef>

#include "mesh/poly_mesh.h"
#include "mesh/raw_mesh.h"

namespace lt::meshio {

// Makes the halfedge texture coordinates OpenMesh read (Options::FaceTexCoord) per vertex,
// splitting every vertex whose corners disagree; the first UV met in face order stays with the
// original vertex, copies are appended. `facts` (normals given, parsed colours) follows the
// copies. Without halfedge texture coordinates, or with a file whose faces mix corners with and
// without them (facts.uv_mix_line, warned), it drops the UVs. Returns the copies added.
std::size_t split_uv_seams(LoadedMesh& loaded, FileFacts& facts);

}  // namespace lt::meshio
