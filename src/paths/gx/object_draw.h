// How a scene object's triangles reach the console under the gx variant's `:draw=` axis
// (gx_variant.h): the vertices the FIFO sends, in order, and the triangles the setup unit builds
// from them. The emulator (gx_path.cpp) sets up exactly these triangles; the FIFO log
// (indexed_recording.h) sends exactly these vertices, so Dolphin sets up the same ones.
// - direct and indexed: the mesh's triangles in its order, GX_TRIANGLES (three vertices a
//   triangle [DSW SetupUnit.cpp SetupTriangle]);
// - strips and list: one triangle strip (mesh/triangle_strips.h: meshoptimizer's vertex-cache
//   order and stripify, joined by degenerate triangles, as GX has no primitive restart), set up
//   as GX_TRIANGLESTRIP sets it up: triangle k is (s[k], s[k+1], s[k+2]) for even k and (s[k],
//   s[k+2], s[k+1]) for odd k [DSW SetupUnit.cpp SetupTriStrip]. Each triangle keeps its winding
//   but may start from another vertex and comes in another order than the list's, which can move
//   pixels (docs/porting-to-the-wii.md "How the vertices are sent").
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "gx/gx_types.h"
#include "paths/gx/gx_variant.h"
#include "scene/triangle_mesh.h"

namespace lt::gx {

// Whether `draw` sends a strip (strips, list) rather than a triangle list.
bool draws_strip(GxVariant::Draw draw);
// Whether `draw` sends indices into arrays rather than each vertex's attributes.
bool draws_indexed(GxVariant::Draw draw);

// The mesh's vertex numbers in the order the FIFO sends them: three a triangle, or the strip.
std::vector<u32> sent_vertex_order(const TriangleMesh& mesh, GxVariant::Draw draw);

// The triangles the setup unit receives from `sent_vertex_order`, in order: the mesh's own, or
// the strip's (degenerate joins included: the clipper culls them as any zero-area triangle).
std::vector<glm::uvec3> setup_order(const TriangleMesh& mesh, GxVariant::Draw draw);

}  // namespace lt::gx
