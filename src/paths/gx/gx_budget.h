// The gx path's budget (gx.md §2): what each pass program uses of the Wii's GX, counted on the
// GX state the program leaves (never on its text), against the hardware limits of
// gx-hardware.md §4. `ltrender budget SCENE --path gx` counts the generated programs,
// `ltrender budget FILE.c` a program file.
#pragma once

#include <string>
#include <vector>

#include "gx/vertex_cost.h"
#include "gx/vertex_storage.h"
#include "paths/budget/report.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/gx_state.h"
#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

struct GxCounts {
  int tev_stages = 0, texgens = 0, texture_maps = 0, channels = 0, lights_per_channel = 0,
      konst_colors = 0, tev_registers = 0, vertex_attributes = 0;
};
GxCounts count_program(const GxState& state);

struct GxProfile {
  std::string name, summary;
  GxCounts limits;
  std::string source;
};
// wii-tev (the Wii / GameCube GX).
const std::vector<GxProfile>& gx_profiles();

// One row (scope pass) per pass program, named "material M pass N (function)" where the
// material is known, else by its function; one row (scope material) per material with its passes
// (additive EFB blending: no hardware limit). `variant` "" is t=vertex, `profile` "" wii-tev.
budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile);
budget::Report gx_budget_file(const std::string& program_file, const std::string& profile);

// The frame's vertex cost on the console (gx/vertex_cost.h) for a scene's draws: every pass of
// every material draws its objects, each with the attributes the pass sends
// (fifo/cp_registers.h sent_attributes: what the FIFO log sends), once in ltrender's F32
// immediate mode and once as a game ships the mesh: stored as `storage` says
// (gx/vertex_storage.h), indexed, one strip a mesh (mesh/triangle_strips.h), in display lists.
// - MEM1 arrays: an object's position, normal, colour and UV arrays once (every pass indexes
//   them); the t of each pass's light (GX_TEX_S, t=vertex) an array of its own, which the CPU
//   rewrites every frame.
// - Display lists: one per object and vertex descriptor (passes that send the same attributes
//   call the same list, with their own t array set).
// - FIFO a frame: per draw, GX_SetArray for each array and GX_CallDispList.
// Not counted (the same both ways): the state each pass loads (VCD, VAT, XF, BP registers).
// Throws InputError(origin, storage key, ...) where `storage` cannot hold a mesh's values.
struct FrameVertexCost {
  DrawCost immediate;     // F32, GX_TRIANGLES, every frame (what ltrender sends today)
  DrawCost display_list;  // `storage`, indexed, stripped, display lists
  std::size_t refreshed_array_bytes = 0;  // the t arrays (part of display_list.array_bytes)
};
FrameVertexCost frame_vertex_cost(const Scene& scene, const ScenePrograms& programs,
                                  const VertexStorage& storage, const std::string& origin);

// The storage `budget --path gx` compares F32 immediate mode with (docs/budget.md).
inline constexpr const char* kBudgetVertexStorage = "vtx=s16,nrm=s8,clr=rgb565,uv=s16";

}  // namespace lt::gx
