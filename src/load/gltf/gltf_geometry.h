// Mesh primitives (glTF 2.0 §3.7.2) as TriangleMesh: POSITION, NORMAL (computed where missing),
// COLOR_0, TEXCOORD_n and the indices; triangle lists, strips and fans as triangles
// (gltf_topology.h).
#pragma once

#include "load/gltf/gltf_description.h"
#include "load/gltf/gltf_notes.h"

namespace lt::gltf {

// The load stage of primitive `d`: its mesh decoded, checked against its material `mat` (the
// Scene's d.material.index) and placed in world space, its notes appended to `notes`. Throws
// InputError naming the pointer for: a mode that carries no surface (the importer skips points and
// lines before; this names any other), an index or vertex count that does not fit the mode, a
// missing POSITION, NaN, Inf or |x| > kMaxCoordinate positions, indices that are not unsigned
// integers or reach past the vertices, attributes of different lengths, any accessor error
// (gltf_accessor.h), the scene's `vertices` passing kMaxSceneVertices, a COLOR_0 or TEXCOORD_n the
// material reads and the primitive lacks, and a vertex its node puts beyond the coordinate limit.
// The UVs are TEXCOORD_<set> (through its transform), those its material's albedo map reads:
// d.material.uv.
TriangleMesh load_primitive(const Document& doc, const PrimitiveDescription& d, const Material& mat,
                            std::size_t& vertices, Notes& notes);

}  // namespace lt::gltf
