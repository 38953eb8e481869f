// What drawing a mesh costs the console, as exact counts (no time: no public source states how
// long the GP takes for any of it): bytes a vertex, the draw commands' bytes, the MEM1 bytes of
// arrays and display lists, the FIFO bytes a frame, the vertices the XF transforms and lights,
// the triangles the setup unit gets. Two ways of sending a mesh are counted:
// - immediate mode, what ltrender's F32 stream does today: GX_Begin(GX_TRIANGLES) every frame,
//   three vertices a triangle, every attribute's bytes in the FIFO;
// - a display list built once, what a game does: the mesh as indexed arrays in MEM1, drawn as one
//   triangle strip (mesh/triangle_strips.h) of index-only vertices inside the list, the frame
//   sending GX_SetArray for each array and GX_CallDispList.
// Commands as libogc writes them: GX_Begin is an opcode byte (primitive | format) and a u16
// vertex count [OGC gx.c GX_Begin L2642]; GX_CallDispList is 0x40, the list's address and size,
// 9 bytes [OGC gx.c L2180-2191]; a CP register load is 0x08, the register, a u32, 6 bytes
// [OGC gx.c GX_LOAD_CP_REG L36-40], and GX_SetArray writes two (base, stride) [OGC gx.c
// L2283-2293]. A display list's size is a multiple of 32 bytes, padded with GX_NOP [OGC gx.h
// GX_EndDispList L2016-2021]; arrays start 32-byte aligned and are flushed by cache line
// (DCFlushRange [OGC gc/ogc/cache.h L123-139]), so each is counted in whole 32-byte lines.
#pragma once

#include <cstddef>
#include <vector>

#include "gx/vertex_quantiser.h"

namespace lt::gx {

inline constexpr std::size_t kGxBeginBytes = 3, kCallDisplayListBytes = 9, kCpLoadBytes = 6,
                             kCacheLineBytes = 32;
// GX_Begin's count is a u16 [OGC gx.h L2055].
inline constexpr std::size_t kMaxBeginVertices = 65535;

struct DrawCost {
  std::size_t vertex_bytes =
      0;  // one vertex in the stream (VertexLoader::vertex_size); summed: the largest
  std::size_t vertices = 0;            // vertices sent: what the XF transforms and lights
  std::size_t triangles = 0;           // triangles set up (a strip's degenerate joins included)
  std::size_t draws = 0;               // GX_Begin commands
  std::size_t command_bytes = 0;       // those commands with their vertices
  std::size_t array_bytes = 0;         // MEM1: the indexed arrays, 32-byte lines
  std::size_t display_list_bytes = 0;  // MEM1: the display list, 32-byte padded (0: immediate)
  std::size_t fifo_bytes = 0;          // what one draw of the mesh sends through the FIFO
  DrawCost& operator+=(const DrawCost& o);
};

// GX_Begin counts for `vertices` vertices of a triangle list (draws of at most 65,535, a
// multiple of 3, so none splits a triangle) or of one strip (draws of at most 65,534, even so
// each next draw keeps the strip's parity, each repeating the last two vertices before it).
std::vector<std::size_t> list_draw_counts(std::size_t vertices);
std::vector<std::size_t> strip_draw_counts(std::size_t vertices);

// `triangles` triangles sent in immediate mode, `vertex_bytes` bytes a vertex.
DrawCost immediate_list_cost(std::size_t triangles, std::size_t vertex_bytes);
// A strip of `strip_vertices` vertices sent in immediate mode (GX_TRIANGLESTRIP draws of
// strip_draw_counts), `vertex_bytes` bytes a vertex.
DrawCost immediate_strip_cost(std::size_t strip_vertices, std::size_t vertex_bytes);
// `draw` (of index-only vertices) over `arrays`: their MEM1 bytes, and the GX_SetArray of each
// array the frame sends before the draw.
DrawCost indexed_cost(DrawCost draw, const IndexedArrays& arrays);
// `draw` (of index-only vertices) recorded in a display list: the list's MEM1 bytes, and the
// frame sends GX_CallDispList instead of the draw's commands.
DrawCost in_display_list(DrawCost draw);
// A strip of `strip_vertices` vertices of `vertex_bytes` (index) bytes in a display list, over
// `arrays`: the frame sends each array's GX_SetArray and the call.
DrawCost display_list_strip_cost(std::size_t strip_vertices, std::size_t vertex_bytes,
                                 const IndexedArrays& arrays);

// `bytes` rounded up to whole 32-byte lines.
std::size_t cache_lines_bytes(std::size_t bytes);

}  // namespace lt::gx
