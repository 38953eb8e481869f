#include "paths/gx/gx_budget.h"

#include <algorithm>
#include <map>
#include <set>

#include "core/error.h"
#include "gx/fifo/cp_registers.h"
#include "gx/texture_format.h"
#include "gx/tmem.h"
#include "mesh/triangle_strips.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/scene_vertices.h"

namespace lt::gx {

namespace {

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
  auto add = [&](const std::string& key, std::size_t v) {
    r.details.push_back({key, "", static_cast<int>(v)});
  };
  add("f32_vertex_bytes", c.immediate.vertex_bytes);
  add("f32_fifo_bytes", c.immediate.fifo_bytes);
  add("f32_xf_vertices", c.immediate.vertices);
  add("f32_triangles", c.immediate.triangles);
  r.details.push_back({"stored_vertex_storage", kBudgetVertexStorage, std::nullopt});
  add("stored_vertex_bytes", c.display_list.vertex_bytes);
  add("stored_array_bytes", c.display_list.array_bytes);
  add("stored_refreshed_array_bytes", c.refreshed_array_bytes);
  add("stored_display_list_bytes", c.display_list.display_list_bytes);
  add("stored_fifo_bytes", c.display_list.fifo_bytes);
  add("stored_xf_vertices", c.display_list.vertices);
  add("stored_triangles", c.display_list.triangles);
  r.notes.push_back(
      "vertex figures are exact counts a frame (bytes, vertices, triangles), not time: no public "
      "source states how long the console takes");
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
  const SceneView view = SceneView::of(scene);
  std::map<size_t, VertexStream> streams;
  std::map<size_t, ObjectSpaceMesh> object_meshes;  // what a game stores: object space
  std::map<size_t, std::vector<u32>> strips;
  std::set<std::pair<size_t, int>> arrays_placed;                // (object, array) in MEM1
  std::set<std::pair<size_t, std::array<u32, 2>>> lists_placed;  // (object, VCD)
  for (const MaterialDraw& d : programs.draws(scene)) {
    const GxState& state = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
    const VertexDescriptor sent = fifo::sent_attributes(state);
    const TexCoordFormats formats = fifo::sent_formats(state.texcoord_formats);
    for (size_t object : d.objects) {
      const TriangleMesh& mesh = scene.objects[object].mesh;
      cost.immediate +=
          immediate_list_cost(mesh.triangles.size(), fifo::vertex_size(sent, formats));
      if (!streams.count(object)) {
        streams.emplace(object, make_vertex_stream(scene, scene.objects[object], view));
        object_meshes.emplace(object, object_space_mesh(scene.objects[object], view));
        std::vector<u32> list;
        for (const glm::uvec3& tri : mesh.triangles) list.insert(list.end(), {tri.x, tri.y, tri.z});
        strips[object] = triangle_strip(list, mesh.positions.size());
      }
      const ObjectSpaceMesh& stored = object_meshes.at(object);
      const VertexAttributeData data =
          pass_vertex_data(stored.position, stored.normal, streams.at(object), sent, formats,
                           static_cast<size_t>(d.pass));
      const VertexAttributeFormat format = storage_format(storage, data, origin);
      const IndexedArrays arrays = index_attributes(quantise_attributes(data, format), origin);
      const VertexInputs inputs = indexed_inputs(arrays);
      const VertexLoader loader(inputs, format, origin);
      DrawCost draw = display_list_strip_cost(strips[object].size(), loader.vertex_size(), arrays);
      // MEM1 holds an object's arrays and lists once; a pass's t array is its own.
      draw.array_bytes = 0;
      for (int a : arrays.arrays) {
        const auto i = static_cast<size_t>(a);
        const bool per_pass =
            a >= kArrayTexCoord0 && data.texcoord_components[i - kArrayTexCoord0] == 1;
        const size_t bytes = cache_lines_bytes(arrays.bytes[i].size());
        if (per_pass) {
          draw.array_bytes += bytes;
          cost.refreshed_array_bytes += bytes;
        } else if (arrays_placed.insert({object, a}).second) {
          draw.array_bytes += bytes;
        }
      }
      if (!lists_placed.insert({object, pack_vertex_inputs(inputs)}).second)
        draw.display_list_bytes = 0;
      cost.display_list += draw;
    }
  }
  return cost;
}

}  // namespace lt::gx
