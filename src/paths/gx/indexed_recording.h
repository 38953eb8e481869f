// The FIFO log of an object drawn under :draw=indexed, strips or list (gx_variant.h,
// object_draw.h): what a port sends for it, so Dolphin plays the very commands.
// - The pass's attributes, stored as the variant says (F32 for the default storage: the
//   camera-relative stream; else the object's own coordinates with its matrices), quantised and
//   put in arrays of their distinct elements (gx/vertex_quantiser.h index_attributes: GX_INDEX8
//   for at most 255 elements, else GX_INDEX16; a pass's t one element per vertex, the array a
//   port's CPU rewrites every frame under the same indices), each array's bytes a memory update at
//   a 32-byte aligned address (GX_SetArray keeps the base's 26 bits; libogc's own arrays are
//   32-byte aligned for DCFlushRange [OGC gc/ogc/cache.h L123-139]).
// - CP: VCD with each attribute's index type, the VAT of the storage, and each array's base
//   (CP 0xA0 + n, a physical address) and stride (CP 0xB0 + n) [OGC gx.c GX_SetArray
//   L2283-2293] [DHW CPMemory.h CPArray].
// - The draws: the vertices' indices, GX_TRIANGLES (indexed) or GX_TRIANGLESTRIP (strips, list)
//   in draws of at most 65,535 vertices (gx/vertex_cost.h list_draw_counts, strip_draw_counts).
// - :draw=list: those draws are the bytes of a display list (padded with GX_NOP to a multiple of
//   32 bytes [OGC gx.h GX_EndDispList L2016-2021]), a memory update of their own, and the FIFO
//   sends GX_CallDispList: 0x40, the list's address, its size [OGC gx.c GX_CallDispList
//   L2180-2191]; Dolphin's command processor reads the list from RAM at that address [DHW
//   OpcodeDecoding.cpp GX_CMD_CALL_DL], where the FIFO player has written the update [DHW
//   FifoPlayer.cpp WriteMemory].
//
// Memory: arrays and lists take 0x00a00000-0x01000000, between the clearing copy's target and
// the FIFO ring (frame_recording.h's map), each distinct block once a frame.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gx/fifo/fifo_log.h"
#include "gx/vertex_stage.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/scene_vertices.h"
#include "scene/triangle_mesh.h"

namespace lt::gx::fifo {

inline constexpr u32 kVertexMemoryBase = 0x00a00000, kVertexMemoryEnd = 0x01000000;
// GX_TRIANGLESTRIP 0x98 = 0x80 | 3 << 3 [OGC gx.h L163]; GX_CallDispList's opcode [OGC gx.c
// L2180-2191] [DHW OpcodeDecoding.h Opcode::GX_CMD_CALL_DL]; GX_NOP [DHW OpcodeDecoding.h].
inline constexpr u8 kPrimitiveTriangleStrip = 3, kCallDisplayList = 0x40, kNop = 0x00;
// MemoryUpdate::Type VERTEX_STREAM [DHW FifoDataFile.h]: the player writes an update's bytes
// whatever its type [DHW FifoPlayer.cpp WriteMemory].
inline constexpr u8 kMemoryUpdateVertexStream = 0x04;

// The arrays and display lists of one frame at their addresses: each distinct block once.
class VertexMemory {
 public:
  explicit VertexMemory(std::string file) : file_(std::move(file)) {}
  // The address of `bytes`, and whether it is new to the frame (its bytes must be sent). Throws
  // InputError(file, "vertices", ...) when the frame's blocks outgrow the region.
  std::pair<u32, bool> place(const std::vector<u8>& bytes);

 private:
  std::string file_;
  u32 next_ = kVertexMemoryBase;
  std::vector<std::pair<std::vector<u8>, u32>> placed_;
};

// One object in one pass: `stream` the frame's F32 stream, `object_mesh` the object's own
// coordinates and matrices where the variant stores the mesh (else nullptr: the F32 stream's
// camera-relative positions). Writes the matrices, VCD, VAT, arrays and draws to `out`, the
// blocks' memory updates to `frame`.
void draw_indexed_object(CommandStream& out, FifoFrame& frame, VertexMemory& memory,
                         const GxState& state, const VertexStream& stream,
                         const ObjectSpaceMesh* object_mesh, const TriangleMesh& mesh,
                         const GxVariant& variant, size_t pass);

}  // namespace lt::gx::fifo
