// The gx path's budget (`ltrender budget SCENE --path gx`): the pass programs it generates for a
// scene, counted and checked as any GX program is (budget/gx_program_budget.h), and what the
// frame's vertices and textures cost the console (frame_vertex_cost, frame_texture_cost).
#pragma once

#include <string>

#include "budget/gx_program_budget.h"
#include "gx/vertex_cost.h"
#include "gx/vertex_storage.h"
#include "paths/gx/gx_path.h"
#include "scene/scene.h"

namespace lt::gx {

// `variant` "" is t=vertex, `profile` "" wii-tev.
budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile);

// The frame's vertex cost on the console (gx/vertex_cost.h) for a scene's draws: every pass of
// every material draws its objects, each with the attributes the pass sends
// (fifo/cp_registers.h sent_attributes: what the FIFO log sends), once in ltrender's F32
// immediate mode and once as a game ships the mesh: in each object's own coordinates
// (scene_vertices.h object_space_mesh), stored as `storage` says (gx/vertex_storage.h), indexed,
// one strip a mesh (mesh/triangle_strips.h), in display lists.
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

// The textures a scene's frame loads, as MEM1 holds them: each distinct texture once (passes and
// materials that load the same texels share one copy), its bytes by GX_GetTexBufferSize's rule
// (gx/texture_format.h level_bytes: whole tiles), and a colour-indexed texture's palette (2 bytes
// an entry, from a 32-byte boundary: GX_InitTlutObj keeps the palette's address shifted right by
// 5 [OGC gx.c GX_InitTlutObj]).
// TMEM (gx/tmem.h): each map of a draw in the cache region libogc's default callback gives it
// (by map, format, mipmaps), occupying its bytes up to the region's 64 KiB, and a colour-indexed
// map's palette's TLUT region (GX_LoadTlut loads the whole region: 512 bytes for GX_TLUT0..15,
// 2 KiB for GX_BIGTLUT0..3); `tmem_bytes` is the most one draw's
// maps occupy at once. A texture over its region's 64 KiB is drawn but streamed through the
// cache (counted in `textures_over_cache`); two maps of one draw in overlapping regions evict
// each other (`overlapping_regions`). The frame's maps fit TMEM when both are 0.
struct FrameTextureCost {
  std::size_t textures = 0;
  std::size_t texture_bytes = 0;
  std::size_t tlut_bytes = 0;
  std::size_t tmem_bytes = 0;
  std::size_t textures_over_cache = 0;
  std::size_t overlapping_regions = 0;
  bool fits_tmem() const { return textures_over_cache == 0 && overlapping_regions == 0; }
};
FrameTextureCost frame_texture_cost(const Scene& scene, const ScenePrograms& programs);

// The storage `budget --path gx` compares F32 immediate mode with (docs/budget.md).
inline constexpr const char* kBudgetVertexStorage = "vtx=s16,nrm=s8,clr=rgb565,uv=s16";

}  // namespace lt::gx
