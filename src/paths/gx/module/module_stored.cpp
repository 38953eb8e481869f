#include "paths/gx/module/module_stored.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>
#include <vector>

#include "core/error.h"
#include "gx/program/pass_programs.h"
#include "gx/vertex_cost.h"
#include "gx/vertex_storage.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/object_draw.h"
#include "paths/gx/scene_draw_cost.h"
#include "paths/gx/scene_vertices.h"

namespace lt::gx {

std::string c_double(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  std::string s = buf;
  if (s.find_first_of(".en") == std::string::npos) s += ".0";
  return s;
}

namespace {

// GX_SetVtxAttrFmt's count and type of array `a` as `format` stores it (plan_emitter.cpp
// vertex_format writes the same names for a pass's declaration).
std::string format_arguments(int a, const VertexAttributeFormat& format) {
  if (a == kArrayPosition) {
    const CoordinateFormat& c = format.position;
    return "GX_POS_XYZ, " + component_type_name(c.type) + ", " + std::to_string(c.frac);
  }
  if (a == kArrayNormal) {
    const NormalFormat& n = format.normal;
    return std::string(!n.nbt     ? "GX_NRM_XYZ, "
                       : n.index3 ? "GX_NRM_NBT3, "
                                  : "GX_NRM_NBT, ") +
           component_type_name(n.type) + ", 0";
  }
  if (a < kArrayTexCoord0) {
    const ColorFormat& c = format.color[static_cast<size_t>(a - kArrayColor0)];
    return std::string(c.alpha ? "GX_CLR_RGBA, " : "GX_CLR_RGB, ") + color_type_name(c.type) +
           ", 0";
  }
  const CoordinateFormat& c = format.texcoord[static_cast<size_t>(a - kArrayTexCoord0)];
  return std::string(c.components == 1 ? "GX_TEX_S, " : "GX_TEX_ST, ") +
         component_type_name(c.type) + ", " + std::to_string(c.frac);
}

template <typename T>
void put_numbers(std::ostringstream& o, const std::vector<T>& values) {
  for (size_t i = 0; i < values.size(); ++i)
    o << (i ? (i % 24 ? "," : ",\n    ") : "\n    ") << static_cast<unsigned>(values[i]);
}

// Where object `o` stands: A (rows), t and A^-T (rows) of its transform, in double, as
// object_space_mesh takes them (glm matrices are column-major: row r, column c is [c][r]).
std::string object_place(const SceneObject& o, const std::string& name) {
  const glm::dmat4 m = o.transform.matrix();
  const glm::dmat3 a(m), normal = glm::transpose(glm::inverse(a));
  std::ostringstream out;
  auto rows = [&](const glm::dmat3& x) {
    out << "{";
    for (int r = 0; r < 3; ++r) {
      out << (r ? ",\n     {" : "{");
      for (int c = 0; c < 3; ++c) out << (c ? ", " : "") << c_double(x[c][r]);
      out << "}";
    }
    out << "}";
  };
  out << "static const ltr_object_place " << name << " = {";
  rows(a);
  out << ",\n    {" << c_double(m[3][0]) << ", " << c_double(m[3][1]) << ", " << c_double(m[3][2])
      << "},\n    ";
  rows(normal);
  out << "};\n";
  return out.str();
}

struct StoredDraw {
  std::string place, arrays, draw_vertices, indices, list;
  size_t array_count = 0, draw_count = 0, list_capacity = 0;
  bool strip = false;
  // t=vertex: arrays[t_array] is the pass's t, which the CPU rewrites every frame (-1: none).
  int t_array = -1;
  bool t_auto_frac = false;
};

// The pass's t (t=vertex): the one-component coordinate pass_vertex_data puts in GX_VA_TEX0.
bool is_t_array(int a, const VertexAttributeData& attributes) {
  return a >= kArrayTexCoord0 &&
         attributes.texcoord_components[static_cast<size_t>(a - kArrayTexCoord0)] == 1;
}

}  // namespace

std::string stored_module_refusal(const GxVariant& variant) {
  if (variant.storage.is_default() || !draws_indexed(variant.draw))
    return "--format module sends a stored mesh indexed (:draw=indexed, strips or list with a "
           "storage :vtx= :nrm= :clr= :uv=) or the F32 mesh directly, not this combination";
  return "";
}

std::string stored_meshes_c(const Scene& scene, const ScenePlan& plan, const GxVariant& variant) {
  const SceneView view = SceneView::of(scene);
  std::ostringstream data, table;
  // Keyed by the bytes as a string: GCC 12 warns falsely (-Wstringop-overread) on comparing
  // vector<u8> keys.
  std::map<std::string, std::string> array_names;
  // draw_of[object][pass]: the object's entry in ltrender_stored_draws.
  std::vector<std::vector<size_t>> draw_of(scene.objects.size());
  std::vector<StoredDraw> draws;
  size_t most_t_vertices = 0;
  for (size_t i = 0; i < scene.objects.size(); ++i) {
    const SceneObject& o = scene.objects[i];
    const auto m = std::find_if(plan.materials.begin(), plan.materials.end(),
                                [&](const MaterialPlan& mp) { return mp.material == o.material; });
    if (m == plan.materials.end()) continue;
    const std::string place = "ltrender_place_" + std::to_string(i);
    data << object_place(o, place);
    const VertexStream stream = make_vertex_stream(scene, o, view);
    const ObjectSpaceMesh mesh = object_space_mesh(o, view);
    const std::vector<u32> order = sent_vertex_order(o.mesh, variant.draw);
    const bool strip = draws_strip(variant.draw);
    for (size_t p = 0; p < m->passes.size(); ++p) {
      const auto [sent, formats] = planned_attributes(m->passes[p].vertex);
      const VertexAttributeData attributes =
          pass_vertex_data(mesh.position, mesh.normal, stream, sent, formats, p);
      const VertexAttributeFormat format = storage_format(variant.storage, attributes, "--variant");
      const IndexedArrays arrays =
          index_attributes(quantise_attributes(attributes, format), "--variant");
      StoredDraw d;
      d.place = place;
      d.strip = strip;
      d.array_count = arrays.arrays.size();
      const std::string id = "ltrender_o" + std::to_string(i) + "_p" + std::to_string(p);
      std::ostringstream arr;
      size_t index_bytes = 0;
      for (int a : arrays.arrays) {
        const auto n = static_cast<size_t>(a);
        // The pass's t array is this object's and pass's own, rewritten every frame
        // (ltr_stored_write_t): zeros until then, shared with nothing.
        const bool t = is_t_array(a, attributes);
        std::string t_name = id + "_t";
        if (t) {
          d.t_array = static_cast<int>(std::find(arrays.arrays.begin(), arrays.arrays.end(), a) -
                                       arrays.arrays.begin());
          d.t_auto_frac = variant.storage.texcoord.auto_frac &&
                          variant.storage.texcoord.type != ComponentType::F32;
          most_t_vertices = std::max(most_t_vertices, attributes.vertex_count());
          data << "static u8 " << t_name << "[" << arrays.bytes[n].size()
               << "] ATTRIBUTE_ALIGN(32);\n";
        }
        std::string& name =
            t ? t_name : array_names[std::string(arrays.bytes[n].begin(), arrays.bytes[n].end())];
        if (name.empty()) {
          name = "ltrender_array_" + std::to_string(array_names.size() - 1);
          data << "static u8 " << name << "[" << arrays.bytes[n].size()
               << "] ATTRIBUTE_ALIGN(32) = {";
          put_numbers(data, arrays.bytes[n]);
          data << "};\n";
        }
        const bool wide = arrays.input[n] == AttributeInput::Index16;
        index_bytes += (wide ? 2 : 1) * static_cast<size_t>(arrays.indices[n]);
        // An NBT is declared and its array set as GX_VA_NBT, as libogc takes it (plan_emitter.cpp).
        const std::string attribute =
            a == kArrayNormal && format.normal.nbt ? "GX_VA_NBT" : attribute_name(a);
        arr << (arr.tellp() > 0 ? ",\n    " : "\n    ") << "{" << attribute << ", "
            << (wide ? "GX_INDEX16" : "GX_INDEX8") << ", " << format_arguments(a, format) << ", "
            << name << ", " << arrays.bytes[n].size() << ", " << arrays.stride[n] << "}";
      }
      data << "static ltr_stored_array " << id << "_arrays[" << d.array_count << "] = {"
           << arr.str() << "};\n";
      // The draws as put_draws sends them: whole triangles, or a strip whose every next draw
      // starts two vertices back.
      std::vector<size_t> counts =
          strip ? strip_draw_counts(order.size()) : list_draw_counts(order.size());
      std::vector<u16> indices;
      size_t start = 0, command_bytes = 0;
      for (size_t n : counts) {
        for (size_t k = start; k < start + n; ++k)
          for (int a : arrays.arrays)
            indices.push_back(
                static_cast<u16>(arrays.element_of_vertex[static_cast<size_t>(a)][order[k]]));
        command_bytes += 3 + n * index_bytes;
        start += strip ? n - 2 : n;
      }
      d.draw_count = counts.size();
      data << "static const u16 " << id << "_draw_vertices[" << std::max<size_t>(counts.size(), 1)
           << "] = {";
      put_numbers(data, counts.empty() ? std::vector<size_t>{0} : counts);
      data << "};\nstatic const u16 " << id << "_indices[" << std::max<size_t>(indices.size(), 1)
           << "] = {";
      put_numbers(data, indices.empty() ? std::vector<u16>{0} : indices);
      data << "};\n";
      if (variant.draw == GxVariant::Draw::List) {
        // The list's commands padded to 32 bytes, and a line more: libogc's list FIFO ends 4
        // bytes before the buffer does [OGC gx.c GX_BeginDispList].
        d.list_capacity = cache_lines_bytes(command_bytes) + 32;
        d.list = id + "_list";
        data << "static u8 " << d.list << "[" << d.list_capacity << "] ATTRIBUTE_ALIGN(32);\n";
      }
      d.arrays = id + "_arrays";
      d.draw_vertices = id + "_draw_vertices";
      d.indices = id + "_indices";
      draw_of[i].push_back(draws.size());
      draws.push_back(std::move(d));
    }
  }
  std::ostringstream out;
  out << "\n// ---- the stored meshes (converted once at export) ----\n"
      << data.str()
      << "\n// Per object and pass: its place, arrays, draws and (:draw=list) display list.\n"
      << "#define LTRENDER_STORED_DRAWS " << draws.size() << "\n"
      << "static ltr_stored_draw ltrender_stored_draws[" << std::max<size_t>(draws.size(), 1)
      << "] = {";
  if (draws.empty()) out << "{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1, 0}";
  for (size_t k = 0; k < draws.size(); ++k) {
    const StoredDraw& d = draws[k];
    out << (k ? ",\n    " : "\n    ") << "{&" << d.place << ", " << d.array_count << ", "
        << d.arrays << ", " << (d.strip ? "GX_TRIANGLESTRIP" : "GX_TRIANGLES") << ", "
        << d.draw_count << ", " << d.draw_vertices << ", " << d.indices << ", "
        << (d.list.empty() ? "0" : d.list) << ", " << d.list_capacity << ", 0, " << d.t_array
        << ", " << d.t_auto_frac << "}";
  }
  out << "};\n\n"
      << "// Once, before the first frame (after GX_Init): flushes the arrays and builds the "
         "lists.\n"
      << "void ltrender_stored_init(void) {\n"
      << "  ltr_stored_init(ltrender_stored_draws, LTRENDER_STORED_DRAWS);\n"
      << "}\n\n"
      << "// Every frame, after each material's setup (states[m]: ltrender_materials[m]'s pass "
         "states):\n"
      << "// every pass of every material, each of its objects, in ltrender's order (pass by "
         "pass).\n"
      << "// A pass that sends t (t=vertex) first computes it at every vertex of the object's "
         "world-space\n"
      << "// mesh, objects[o] for scene object o (what the setups take; lights[] this frame's), "
         "and\n"
      << "// rewrites and flushes its t array (ltr_stored_write_t); the display list stays.\n";
  if (most_t_vertices > 0) out << "static float ltrender_t_scratch[" << most_t_vertices << "];\n";
  out << "void ltrender_draw_stored(const ltr_view* view, const ltr_light lights[],\n"
      << "    const ltr_mesh objects[], ltr_pass_state* const states[]) {\n";
  if (most_t_vertices == 0) out << "  (void)lights;\n  (void)objects;\n";
  size_t most = 0;
  for (const MaterialPlan& m : plan.materials) most = std::max(most, m.passes.size());
  for (size_t p = 0; p < most; ++p) {
    for (size_t mi = 0; mi < plan.materials.size(); ++mi) {
      const MaterialPlan& m = plan.materials[mi];
      if (p >= m.passes.size()) continue;
      std::vector<size_t> objects;
      for (size_t i = 0; i < scene.objects.size(); ++i)
        if (scene.objects[i].material == m.material) objects.push_back(i);
      if (objects.empty()) continue;
      out << "  " << pass_function_name(m.c_name, static_cast<int>(p)) << "(&states[" << mi << "]["
          << p << "]);\n";
      for (size_t i : objects) {
        const std::string draw = "&ltrender_stored_draws[" + std::to_string(draw_of[i][p]) + "]";
        if (m.passes[p].vertex.t)
          out << "  ltrender_" << m.c_name << "_fill_t(view, lights, " << sent_t_light(m, p)
              << ", &objects[" << i << "], ltrender_t_scratch);\n"
              << "  ltr_stored_write_t(" << draw << ", ltrender_t_scratch);\n";
        out << "  ltr_stored_draw_object(view, " << draw << ");\n";
      }
    }
  }
  out << "}\n";
  return out.str();
}

std::string stored_cost_comment(const Scene& scene, const GxVariant& variant) {
  const ScenePrograms programs = scene_programs_for(scene, variant, "");
  const SceneDrawCost f32 =
      scene_draw_cost(scene, programs, VertexStorage{}, GxVariant::Draw::Direct, "--variant");
  const SceneDrawCost stored =
      scene_draw_cost(scene, programs, variant.storage, variant.draw, "--variant");
  std::ostringstream o;
  o << "// The console's cost of the vertices a frame (as `ltrender budget --path gx --variant` "
       "counts\n// them; exact counts, not time), this module against F32 immediate mode:\n"
    << "//   bytes a vertex " << stored.draw.vertex_bytes << " (F32 " << f32.draw.vertex_bytes
    << "); MEM1: arrays " << stored.draw.array_bytes << " bytes, display lists "
    << stored.draw.display_list_bytes << " bytes;\n"
    << "//   FIFO a frame " << stored.draw.fifo_bytes << " bytes (F32 " << f32.draw.fifo_bytes
    << "); XF vertices " << stored.draw.vertices << " (F32 " << f32.draw.vertices
    << ");\n//   triangles set up " << stored.draw.triangles << " (F32 " << f32.draw.triangles
    << ").\n";
  return o.str();
}

}  // namespace lt::gx
