// The meshes of a module of a stored variant (`export gx --variant vtx=s16/auto:nrm=s8:clr=rgb565
// :draw=list --format module`, docs/porting-to-the-wii.md "The module"): what a game converts
// once and ships, written as C the module carries. Every object in every pass gets the arrays
// ltrender's FIFO log puts in MEM1 for it (paths/gx/indexed_recording.cpp draw_indexed_object:
// pass_vertex_data, storage_format, quantise_attributes, index_attributes: the same calls, so the
// same bytes, quantised once), where the object stands (its transform, for the runtime's
// ltr_object_matrices), and its draws in the FIFO log's order (object_draw.h sent_vertex_order,
// vertex_cost.h list_draw_counts / strip_draw_counts), as a display list under :draw=list.
// The runtime's ltrender_gx_stored.c sends them.
#pragma once

#include <string>

#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

// A double as C reads it back exactly (17 significant digits).
std::string c_double(double v);

// Why the module cannot carry the variant's stored mesh, or "" when it can: it stores a mesh
// (a storage axis) and indexes it (:draw=indexed, strips or list).
std::string stored_module_refusal(const GxVariant& variant);

// The stored meshes as C: the arrays (32-byte aligned), each object's place, the draw table
// ltr_stored_init and ltr_stored_draw_object take, ltrender_stored_init() and
// ltrender_draw_stored(view, lights, objects, states), which draws every pass of every material
// in the emulator's order (gx_path.h ScenePrograms::draws). A pass that sends t (t=vertex) has a
// t array of its own per object, one element per vertex (vertex_quantiser.h AttributeElements
// per_vertex, as the FIFO log's), which ltrender_draw_stored fills each frame (the material's
// _fill_t over objects[o], the game's world-space mesh, then ltr_stored_write_t: quantised as the
// log's, flushed) before the object's draw; the display lists index it and never change. Throws
// InputError("--variant", ...) where the storage cannot hold a mesh's values.
std::string stored_meshes_c(const Scene& scene, const ScenePlan& plan, const GxVariant& variant);

// The module's comment on the stored variant's cost (scene_draw_cost.h, what `budget --path gx`
// counts for the variant): bytes a vertex, MEM1 array and display-list bytes, FIFO bytes a frame,
// beside ltrender's F32 immediate mode.
std::string stored_cost_comment(const Scene& scene, const GxVariant& variant);

}  // namespace lt::gx
