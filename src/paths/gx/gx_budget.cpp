#include "paths/gx/gx_budget.h"

#include <bitset>
#include <map>
#include <set>

#include "core/error.h"
#include "core/find_named.h"
#include "mesh/triangle_strips.h"
#include "paths/gx/fifo/cp_registers.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/program/parser.h"
#include "paths/gx/vertex_stage.h"

namespace lt::gx {

namespace {

// A colour operand that reads a TEV register (CPREV/APREV/C0/A0/..: 0..7) names register
// sel / 2; the alpha operands APREV/A0/A1/A2 (0..3) name register sel.
void count_registers(const TevStage& s, std::set<int>& regs) {
  for (u8 sel : {s.color.a, s.color.b, s.color.c, s.color.d}) {
    if (sel < 8) regs.insert(sel / 2);
  }
  for (u8 sel : {s.alpha.a, s.alpha.b, s.alpha.c, s.alpha.d}) {
    if (sel < 4) regs.insert(sel);
  }
  regs.insert(s.color.dest);
  regs.insert(s.alpha.dest);
}

// A konst selector 12..31 reads K0..K3 (the low two bits); 0..7 are fixed fractions
// [HWT gxtest/tev.cpp KonstTest].
void count_konst(const TevStage& s, std::set<int>& konst) {
  const bool colour_reads =
      s.color.a == 14 || s.color.b == 14 || s.color.c == 14 || s.color.d == 14;
  const bool alpha_reads = s.alpha.a == 6 || s.alpha.b == 6 || s.alpha.c == 6 || s.alpha.d == 6;
  if (colour_reads && s.konst_color_sel >= 12) konst.insert(s.konst_color_sel & 3);
  if (alpha_reads && s.konst_alpha_sel >= 12) konst.insert(s.konst_alpha_sel & 3);
}

std::vector<budget::Resource> resources(const GxCounts& c, const GxCounts& lim) {
  // A limit below 0 is none.
  auto row = [&](const char* key, const char* label, int GxCounts::*n) {
    return budget::Resource{
        key, label, c.*n, lim.*n >= 0 ? std::optional<int>(lim.*n) : std::nullopt, "", {}};
  };
  return {row("tev_stages", "TEV stages", &GxCounts::tev_stages),
          row("texgens", "texgens", &GxCounts::texgens),
          row("texture_maps", "texture maps", &GxCounts::texture_maps),
          row("channels", "colour channels", &GxCounts::channels),
          row("lights_per_channel", "lights per channel", &GxCounts::lights_per_channel),
          row("konst_colors", "konst colours", &GxCounts::konst_colors),
          row("tev_registers", "TEV registers", &GxCounts::tev_registers),
          row("vertex_attributes", "vertex attributes", &GxCounts::vertex_attributes)};
}

// Throws InputError("--profile", ...) naming the valid profiles.
const GxProfile& find_gx_profile(const std::string& name) {
  return find_named(gx_profiles(), name, "--profile", "gx profile");
}

budget::Report report_of(const std::vector<std::vector<PassProgram>>& by_material,
                         const std::vector<std::string>& material_names,
                         const std::string& profile) {
  const GxProfile& prof = find_gx_profile(profile.empty() ? "wii-tev" : profile);
  budget::Report r;
  r.path = "gx";
  r.profiles = {{prof.name, "", prof.summary + " (" + prof.source + ")"}};
  std::vector<budget::Item> materials;
  for (size_t m = 0; m < by_material.size(); ++m) {
    std::string material;
    for (const PassProgram& p : by_material[m]) {
      budget::Item b;
      b.scope = budget::Scope::Pass;
      b.material = m < material_names.size() ? material_names[m] : p.material;
      material = b.material;
      b.name = b.material.empty() ? p.name
                                  : "material " + b.material + " pass " + std::to_string(p.pass) +
                                        " (" + p.name + ")";
      b.profile = prof.name;
      b.resources = resources(count_program(p.state), prof.limits);
      r.items.push_back(std::move(b));
    }
    if (by_material[m].empty()) continue;
    budget::Item passes;
    passes.scope = budget::Scope::Material;
    passes.name = (material.empty() ? "(whole file)" : "material " + material) + ": passes";
    passes.material = material;
    passes.resources = {{"passes", "passes", static_cast<int>(by_material[m].size()), {}, "", {}}};
    passes.note = "passes: additive EFB blending, no hardware limit";
    materials.push_back(std::move(passes));
  }
  r.items.insert(r.items.end(), materials.begin(), materials.end());
  return r;
}


// What pass `pass` sends of an object's mesh, as floats before storage: the mesh as a port
// stores it, in world space (the position matrix places it), not ltrender's camera-relative
// stream; normals, colours, UVs and the pass's light's t as the stream has them.
VertexAttributeData pass_vertex_data(const TriangleMesh& mesh, const VertexStream& stream,
                                     const VertexDescriptor& sent, const TexCoordFormats& formats,
                                     size_t pass) {
  VertexAttributeData d;
  for (const glm::dvec3& p : mesh.positions) d.position.emplace_back(p);
  if (sent.has(kVaNrm)) d.normal = stream.normal;
  if (sent.has(kVaClr0)) d.color[0] = stream.color;
  if (sent.has(kVaClr1)) d.color[1] = stream.color;
  const std::vector<float>* t =
      pass < stream.t_per_light.size() ? &stream.t_per_light[pass] : nullptr;
  for (int n = 0; n < kMaxTexGens; ++n) {
    if (!sent.has(kVaTex0 + n)) continue;
    const auto i = static_cast<size_t>(n);
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      if (formats.kind[i] == TexCoordFormats::ST)
        d.texcoord[i].push_back(v < stream.uv.size() ? stream.uv[v] : glm::vec2(0.0f));
      else
        d.texcoord[i].emplace_back(t ? (*t)[v] : 0.0f, 0.0f);
    }
    if (formats.kind[i] != TexCoordFormats::ST) d.texcoord_components[i] = 1;
  }
  return d;
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
}  // namespace

GxCounts count_program(const GxState& st) {
  GxCounts c;
  c.tev_stages = st.tev.num_stages;
  c.texgens = st.texgen.num_texgens;
  c.channels = st.lighting.num_channels;
  std::set<int> maps, regs, konst;
  // Counts beyond the hardware's are reported as they are; only the 16 stages that exist and
  // the 2 channels hold state to look at.
  for (int i = 0; i < std::min(st.tev.num_stages, kMaxTevStages); ++i) {
    const TevStage& s = st.tev.stages[static_cast<size_t>(i)];
    if (s.texmap != kTexMapNull) maps.insert(s.texmap);
    count_registers(s, regs);
    count_konst(s, konst);
  }
  c.texture_maps = static_cast<int>(maps.size());
  c.tev_registers = static_cast<int>(regs.size());
  c.konst_colors = static_cast<int>(konst.size());
  for (int ch = 0; ch < std::min(st.lighting.num_channels, kMaxChannels); ++ch) {
    for (int part : {ch, ch + 2}) {
      const ChannelControl& ctl = st.lighting.control[static_cast<size_t>(part)];
      if (ctl.lighting)
        c.lights_per_channel = std::max(c.lights_per_channel,
                                        static_cast<int>(std::bitset<8>(ctl.light_mask).count()));
    }
  }
  c.vertex_attributes = st.vertex.count();
  return c;
}

const std::vector<GxProfile>& gx_profiles() {
  GxCounts wii;
  wii.tev_stages = 16;         // [OGC gx.h L569, L3070]
  wii.texgens = 8;             // [OGC gx.h L279, L2692]
  wii.texture_maps = 8;        // [OGC gx.h L673]
  wii.channels = 2;            // COLOR0A0, COLOR1A1 [OGC gx.h L3003-3011]
  wii.lights_per_channel = 8;  // GX_LIGHT0..7 [OGC gx.h L178-187]
  wii.konst_colors = 4;        // GX_KCOLOR0..3 [OGC gx.h L692-696]
  wii.tev_registers = 4;       // PREV, REG0..2 [OGC gx.h L637-641]
  wii.vertex_attributes = 12;  // GX_VA_POS .. GX_VA_TEX7 that carry data per vertex
  static const std::vector<GxProfile> profiles = {
      {"wii-tev",
       "Wii / GameCube GX: 16 TEV stages, 8 texgens, 8 texture maps, 2 colour "
       "channels, 8 lights, 4 konst colours, PREV + 3 TEV registers",
       wii, "devkitPro/libogc gc/ogc/gx.h; docs/spec/gx-hardware.md section 4"}};
  return profiles;
}

budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile) {
  const GxVariant v = parse_gx_variant(variant.empty() ? "t=vertex" : variant);
  const ScenePrograms programs = scene_programs_for(scene, v, "");
  std::vector<std::string> names;
  for (const Material& m : scene.materials) names.push_back(m.name);
  budget::Report r = report_of(programs.by_material, names, profile);
  r.file = scene.file.string();
  r.input = "scene";
  r.variant = to_string(v);
  add_vertex_cost(r, scene, programs);
  return r;
}

budget::Report gx_budget_file(const std::string& program_file, const std::string& profile) {
  const ProgramFile file = load_program(program_file);
  std::vector<std::vector<PassProgram>> groups;
  std::map<std::string, size_t> index;
  for (PassProgram& p : file_programs(file)) {
    if (!index.count(p.material)) {
      index[p.material] = groups.size();
      groups.emplace_back();
    }
    groups[index[p.material]].push_back(std::move(p));
  }
  budget::Report r = report_of(groups, {}, profile);
  r.file = program_file;
  r.input = "program";
  return r;
}

}  // namespace lt::gx

namespace lt::gx {

FrameVertexCost frame_vertex_cost(const Scene& scene, const ScenePrograms& programs,
                                  const VertexStorage& storage, const std::string& origin) {
  FrameVertexCost cost;
  const SceneView view = SceneView::of(scene);
  std::map<size_t, VertexStream> streams;
  std::map<size_t, std::vector<u32>> strips;
  std::set<std::pair<size_t, int>> arrays_placed;                 // (object, array) in MEM1
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
        std::vector<u32> list;
        for (const glm::uvec3& tri : mesh.triangles) list.insert(list.end(), {tri.x, tri.y, tri.z});
        strips[object] = triangle_strip(list, mesh.positions.size());
      }
      const VertexAttributeData data =
          pass_vertex_data(mesh, streams.at(object), sent, formats, static_cast<size_t>(d.pass));
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
