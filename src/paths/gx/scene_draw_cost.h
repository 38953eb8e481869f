// What a scene's frame of vertices costs the console (gx/vertex_cost.h) under a vertex storage
// and a way of sending the vertices (the gx variant's :vtx= :nrm= :clr= :uv= and :draw= axes):
// the same draws the FIFO log sends (frame_recording.h, indexed_recording.h), counted. Every pass
// of every material draws its objects, each with the attributes the pass sends
// (fifo/cp_registers.h sent_attributes), stored as `storage` says (the default: the F32 stream),
// in the order object_draw.h gives.
// - :draw=direct: every vertex's stored bytes, GX_TRIANGLES.
// - :draw=indexed, strips: each vertex's indices (1 byte an attribute of at most 255 elements,
//   else 2), GX_TRIANGLES or one GX_TRIANGLESTRIP, after a GX_SetArray of each array.
// - :draw=list: the strip in a display list (32-byte padded), the frame sending GX_SetArray for
//   each array and GX_CallDispList.
// MEM1 (indexed): an object's position, normal, colour and UV arrays once (every pass indexes
// them); the t of each pass's light (GX_TEX_S, t=vertex) an array of its own, which the CPU
// rewrites every frame; one display list per object and vertex descriptor (passes that send the
// same attributes call the same list, with their own t array set). Whole 32-byte lines: arrays
// and lists start 32-byte aligned (DCFlushRange works by cache line [OGC gc/ogc/cache.h
// L123-139]; GX_SetArray takes a physical address, and libogc's GX_BeginDispList asks for a
// 32-byte aligned buffer [OGC gx.h GX_BeginDispList]).
// Not counted (the same every way): the state each pass loads (VCD, VAT, XF, BP registers).
#pragma once

#include <string>

#include "gx/vertex_cost.h"
#include "gx/vertex_storage.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

struct SceneDrawCost {
  DrawCost draw;
  std::size_t refreshed_array_bytes = 0;  // the t arrays (part of draw.array_bytes)
};

// Throws InputError(origin, storage key, ...) where `storage` cannot hold a mesh's values, or
// (origin, attribute, ...) where an indexed attribute has more than 65,535 elements.
SceneDrawCost scene_draw_cost(const Scene& scene, const ScenePrograms& programs,
                              const VertexStorage& storage, GxVariant::Draw draw,
                              const std::string& origin);

}  // namespace lt::gx
