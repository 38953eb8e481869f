#include "paths/gx/scene_draw_cost.h"

#include <map>
#include <set>

#include "gx/fifo/cp_registers.h"
#include "paths/gx/object_draw.h"
#include "paths/gx/scene_vertices.h"

namespace lt::gx {

SceneDrawCost scene_draw_cost(const Scene& scene, const ScenePrograms& programs,
                              const VertexStorage& storage, GxVariant::Draw draw,
                              const std::string& origin) {
  SceneDrawCost cost;
  const SceneView view = SceneView::of(scene);
  const bool stored = !storage.is_default();  // sent in object space (scene_vertices.h)
  std::map<size_t, VertexStream> streams;
  std::map<size_t, ObjectSpaceMesh> object_meshes;
  std::map<size_t, std::vector<u32>> orders;
  std::set<std::pair<size_t, int>> arrays_placed;                // (object, array) in MEM1
  std::set<std::pair<size_t, std::array<u32, 2>>> lists_placed;  // (object, VCD)
  for (const MaterialDraw& d : programs.draws(scene)) {
    const GxState& state = programs.by_material[d.material][static_cast<size_t>(d.pass)].state;
    const VertexDescriptor sent = fifo::sent_attributes(state);
    const TexCoordFormats formats = fifo::sent_formats(state.texcoord_formats);
    for (size_t object : d.objects) {
      const SceneObject& o = scene.objects[object];
      if (!streams.count(object)) {
        streams.emplace(object, make_vertex_stream(scene, o, view));
        if (stored) object_meshes.emplace(object, object_space_mesh(o, view));
        orders.emplace(object, sent_vertex_order(o.mesh, draw));
      }
      const VertexStream& stream = streams.at(object);
      const VertexAttributeData data =
          pass_vertex_data(stored ? object_meshes.at(object).position : stream.position,
                           stored ? object_meshes.at(object).normal : stream.normal, stream, sent,
                           formats, static_cast<size_t>(d.pass));
      const VertexAttributeFormat format = storage_format(storage, data, origin);
      const std::vector<AttributeElements> elements = quantise_attributes(data, format);
      if (!draws_indexed(draw)) {
        const VertexLoader loader(sent_inputs(data, AttributeInput::Direct), format, origin);
        cost.draw += immediate_list_cost(o.mesh.triangles.size(), loader.vertex_size());
        continue;
      }
      const IndexedArrays arrays = index_attributes(elements, origin);
      const VertexInputs inputs = indexed_inputs(arrays);
      const size_t vertex_bytes = VertexLoader(inputs, format, origin).vertex_size();
      const size_t sent_vertices = orders.at(object).size();
      DrawCost c = draws_strip(draw) ? immediate_strip_cost(sent_vertices, vertex_bytes)
                                     : immediate_list_cost(sent_vertices / 3, vertex_bytes);
      if (draw == GxVariant::Draw::List) {
        c = in_display_list(c);
        if (!lists_placed.insert({object, pack_vertex_inputs(inputs)}).second)
          c.display_list_bytes = 0;
      }
      c = indexed_cost(c, arrays);
      // MEM1 holds an object's arrays once; a pass's t array is its own.
      c.array_bytes = 0;
      for (int a : arrays.arrays) {
        const auto i = static_cast<size_t>(a);
        const bool per_pass =
            a >= kArrayTexCoord0 && data.texcoord_components[i - kArrayTexCoord0] == 1;
        const size_t bytes = cache_lines_bytes(arrays.bytes[i].size());
        if (per_pass) {
          c.array_bytes += bytes;
          cost.refreshed_array_bytes += bytes;
        } else if (arrays_placed.insert({object, a}).second) {
          c.array_bytes += bytes;
        }
      }
      cost.draw += c;
    }
  }
  return cost;
}

}  // namespace lt::gx
