// The setup unit's front end (gx-hardware.md §2.6): the trivial rejection, the cull test, the
// clipping of a triangle to the view volume in clip space and the perspective divide with the
// viewport, as Dolphin's software renderer does them [DSW Clipper.cpp ProcessTriangle,
// CalcClipMask, IsTriviallyRejected, IsBackface, ClipTriangle, POLY_CLIP, PerspectiveDivide;
// NativeVertexFormat.h OutputVertexData::Lerp]. Every comparison and every float operation is
// the one Dolphin's code makes, in its order: a clipped vertex, a culled sliver and a vertex on
// a clip plane come out as the console emulator has them.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <tuple>

#include "gx/gx_types.h"
#include "gx/transform_unit.h"

namespace lt::gx {

// One vertex as the XF hands it to the setup unit [DSW OutputVertexData]: the clip-space
// position, the screen position the perspective divide makes of it, the two channel colours
// (8 bits: XF lighting ends in integers) and the texture coordinates (s and t already scaled by
// their texture's size, q as the texgen made it).
struct RasterVertex {
  glm::vec4 clip{0};
  glm::vec3 screen{0};
  std::array<Color8, kMaxChannels> color{};
  std::array<glm::vec3, kMaxTexGens> tex{};
};

// What became of one triangle.
enum class TriangleFate : u8 {
  Drawn,        // one or more triangles reach the rasteriser
  Rejected,     // all three vertices outside one clip plane
  Culled,       // removed by the cull mode
  ClippedAway,  // clipping left less than a triangle
};

// The front-facing triangles a triangle becomes: a fan of the clipped polygon, its vertices
// divided and mapped to the screen, each wound as the rasteriser wants it.
struct ClippedTriangles {
  // The 3 input vertices and at most 2 new ones per clip plane [DSW Clipper.cpp
  // NUM_CLIPPED_VERTICES]; a fan of at most 15 corners has at most 13 triangles.
  std::array<RasterVertex, 3 + 2 * 6> vertices;
  std::array<std::array<u8, 3>, 13> triangles;
  int count = 0;
};

// libogc's cull mode (gx_state.h kCull*) as the hardware's genmode field: libogc swaps front
// and back (cm2hw = {0, 2, 1, 3} [OGC gx.c L3931]); the hardware culls mode 1 where the
// clip-space winding is positive and mode 2 where it is not [DSW Clipper.cpp ProcessTriangle].
u8 hardware_cull_mode(u8 gx_cull_mode);

// Rejects, culls and clips the triangle (v0, v1, v2) under `gx_cull_mode` (libogc's value) and
// fills `out` with what reaches the rasteriser. Only `clip`, `color` and `tex` of the inputs
// are read.
TriangleFate clip_triangle(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                           u8 gx_cull_mode, const Viewport& viewport, ClippedTriangles& out);

}  // namespace lt::gx
