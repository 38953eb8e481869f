#include "paths/gx/gx_budget.h"

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "core/error.h"
#include "gx/texture_format.h"
#include "gx/tmem.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/scene_draw_cost.h"

namespace lt::gx {

namespace {

// One draw's figures, each key under `prefix` (docs/budget.md): what the FIFO sends a frame
// and, for an indexed draw (`refreshed_array_bytes` given), the arrays and display list it
// keeps in MEM1.
void add_draw_cost(budget::Report& r, const std::string& prefix, const DrawCost& c,
                   std::optional<std::size_t> refreshed_array_bytes) {
  auto add = [&](const char* key, std::size_t n) {
    r.details.push_back({prefix + key, "", static_cast<int>(n)});
  };
  add("vertex_bytes", c.vertex_bytes);
  if (refreshed_array_bytes) {
    add("array_bytes", c.array_bytes);
    add("refreshed_array_bytes", *refreshed_array_bytes);
    add("display_list_bytes", c.display_list_bytes);
  }
  add("fifo_bytes", c.fifo_bytes);
  add("xf_vertices", c.vertices);
  add("triangles", c.triangles);
}

// The vertex cost details of a scene's budget: F32 immediate mode and kBudgetVertexStorage,
// indexed, stripped, in display lists (docs/budget.md).
void add_vertex_cost(budget::Report& r, const Scene& scene, const ScenePrograms& programs) {
  FrameVertexCost c;
  try {
    c = frame_vertex_cost(scene, programs, parse_vertex_storage(kBudgetVertexStorage, ""), "");
  } catch (const InputError& e) {
    r.notes.push_back(std::string("vertex storage ") + kBudgetVertexStorage +
                      " not counted: " + e.where() + ": " + e.what_only());
    return;
  }
  add_draw_cost(r, "f32_", c.immediate, std::nullopt);
  r.details.push_back({"stored_vertex_storage", kBudgetVertexStorage, std::nullopt});
  add_draw_cost(r, "stored_", c.display_list, c.refreshed_array_bytes);
  r.notes.push_back(
      "vertex figures are exact counts a frame (bytes, vertices, triangles), not time: no public "
      "source states how long the console takes");
}
// The variant's own vertices: its storage and its :draw= (scene_draw_cost.h), as its FIFO log
// sends them.
void add_variant_vertex_cost(budget::Report& r, const Scene& scene, const ScenePrograms& programs,
                             const GxVariant& v) {
  SceneDrawCost c;
  try {
    c = scene_draw_cost(scene, programs, v.storage, v.draw, "--variant");
  } catch (const InputError& e) {
    r.notes.push_back("the variant's vertices not counted: " + e.where() + ": " + e.what_only());
    return;
  }
  add_draw_cost(r, "", c.draw, c.refreshed_array_bytes);
}
void add_texture_cost(budget::Report& r, const Scene& scene, const ScenePrograms& programs) {
  const FrameTextureCost c = frame_texture_cost(scene, programs);
  r.details.push_back({"textures", "", static_cast<int>(c.textures)});
  r.details.push_back({"texture_bytes", "", static_cast<int>(c.texture_bytes)});
  r.details.push_back({"tlut_bytes", "", static_cast<int>(c.tlut_bytes)});
  r.details.push_back({"tmem_bytes", "", static_cast<int>(c.tmem_bytes)});
  r.details.push_back({"tmem_textures_over_cache", "", static_cast<int>(c.textures_over_cache)});
  r.details.push_back({"tmem_overlapping_regions", "", static_cast<int>(c.overlapping_regions)});
  r.details.push_back({"tmem_fits", c.fits_tmem() ? "yes" : "no", std::nullopt});
}

}  // namespace

budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile) {
  const GxVariant v = parse_gx_variant(variant.empty() ? "t=vertex" : variant);
  const ScenePrograms programs = scene_programs_for(scene, v, "");
  std::vector<std::string> names;
  for (const Material& m : scene.materials) names.push_back(m.name);
  budget::Report r = gx_programs_report(programs.by_material, names, profile);
  r.file = scene.file.string();
  r.input = "scene";
  r.variant = to_string(v);
  add_vertex_cost(r, scene, programs);
  add_variant_vertex_cost(r, scene, programs, v);
  add_texture_cost(r, scene, programs);
  return r;
}

FrameTextureCost frame_texture_cost(const Scene& scene, const ScenePrograms& programs) {
  std::vector<const TextureObject*> loaded;
  for (const MaterialDraw& d : programs.draws(scene)) {
    const GxState& state = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
    for (const auto& t : state.textures) {
      if (!t) continue;
      const bool seen = std::any_of(loaded.begin(), loaded.end(), [&](const TextureObject* u) {
        return u->format == t->format && u->width == t->width && u->height == t->height &&
               u->data == t->data && u->tlut == t->tlut;
      });
      if (!seen) loaded.push_back(&*t);
    }
  }
  FrameTextureCost cost;
  cost.textures = loaded.size();
  for (const TextureObject* t : loaded) {
    const std::size_t bytes = level_bytes(static_cast<TexFormat>(t->format), t->width, t->height);
    cost.texture_bytes += bytes;
    cost.tlut_bytes += (t->tlut.size() + 31) & ~std::size_t{31};
    if (bytes > kTexCacheRegionBytes) ++cost.textures_over_cache;
  }
  // TMEM per draw: the maps its state loads, each in its region (gx/tmem.h).
  std::set<std::pair<size_t, int>> counted;  // (material, pass): one state, counted once
  for (const MaterialDraw& d : programs.draws(scene)) {
    if (!counted.insert({d.material, d.pass}).second) continue;
    const GxState& state = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
    std::size_t tmem = 0;
    std::vector<TexCacheRegion> regions;
    for (int map = 0; map < kMaxTexMaps; ++map) {
      const auto& t = state.textures[static_cast<size_t>(map)];
      if (!t) continue;
      const auto format = static_cast<TexFormat>(t->format);
      tmem += texture_tmem_bytes(level_bytes(format, t->width, t->height));
      // A palette's TLUT region, which GX_LoadTlut loads whole (gx/tmem.h).
      if (!t->tlut.empty())
        tmem += static_cast<std::size_t>(tlut_region_entries_at(t->tlut_offset)) * 2;
      const TexCacheRegion region = texture_cache_region(format, false, map);
      for (const TexCacheRegion& other : regions)
        if (regions_overlap(region, other)) ++cost.overlapping_regions;
      regions.push_back(region);
    }
    cost.tmem_bytes = std::max(cost.tmem_bytes, tmem);
  }
  return cost;
}

FrameVertexCost frame_vertex_cost(const Scene& scene, const ScenePrograms& programs,
                                  const VertexStorage& storage, const std::string& origin) {
  FrameVertexCost cost;
  cost.immediate =
      scene_draw_cost(scene, programs, VertexStorage{}, GxVariant::Draw::Direct, origin).draw;
  const SceneDrawCost stored =
      scene_draw_cost(scene, programs, storage, GxVariant::Draw::List, origin);
  cost.display_list = stored.draw;
  cost.refreshed_array_bytes = stored.refreshed_array_bytes;
  return cost;
}

}  // namespace lt::gx
