// Mesh primitives (glTF 2.0 §3.7.2) as TriangleMesh: POSITION, NORMAL (computed where missing),
// COLOR_0, TEXCOORD_n and the indices; triangle lists, strips and fans as triangles
// (gltf_topology.h).
#pragma once

#include <string>
#include <vector>

#include "load/gltf/gltf_document.h"
#include "load/gltf/gltf_textures.h"
#include "scene/triangle_mesh.h"

namespace lt::gltf {

struct PrimitiveMesh {
  TriangleMesh mesh;               // object space of its node
  std::vector<std::string> notes;  // what was read, what was computed, what was ignored
};

// Reads /meshes/{mesh}/primitives/{primitive}. Throws InputError naming the pointer for: a mode
// that carries no surface (the importer skips points and lines before; this names any other), an
// index or vertex count that does not fit the mode, a missing POSITION, NaN, Inf or |x| >
// kMaxCoordinate positions, indices that are not unsigned integers or reach past the vertices,
// attributes of different lengths, and any accessor error (gltf_accessor.h). The UVs are
// TEXCOORD_<uv.set> (through uv.transform), those its material's albedo map reads.
PrimitiveMesh read_primitive(const Document& doc, int mesh, int primitive,
                             const TextureCoordinates& uv = {});

}  // namespace lt::gltf
