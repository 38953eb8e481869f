#include "paths/gx/scene_vertices.h"

#include <algorithm>
#include <glm/glm.hpp>
#include <optional>
#include <utility>

#include "core/error.h"
#include "gx/transform_unit.h"
#include "gx/vertex_loader.h"
#include "image/image.h"
#include "model/translucency.h"
#include "paths/gx/object_draw.h"

namespace lt::gx {

VertexStream make_vertex_stream(const Scene& scene, const SceneObject& object,
                                const SceneView& view) {
  const TriangleMesh& m = object.mesh;
  const Material& mat = scene.materials[static_cast<size_t>(object.material)];
  VertexStream s;
  const size_t n = m.positions.size();
  const glm::mat3 rotation(view.view);  // XF matrices are float
  for (size_t v = 0; v < n; ++v) {
    const glm::vec3 p(m.positions[v] - view.eye), nrm(m.normals[v]);
    s.position.push_back(p);
    s.normal.push_back(nrm);
    s.eye_position.push_back(rotation * p);
    s.eye_normal.push_back(rotation * nrm);
    Color8 c{255, 255, 255, 255};
    if (m.has_colors()) {
      for (int ch = 0; ch < 3; ++ch) c[ch] = to_unorm8(m.colors[v][ch]);
    }
    s.color.push_back(c);
  }
  for (const glm::dvec2& uv : m.uvs) s.uv.emplace_back(uv);
  for (const Light& light : scene.lights) {
    std::vector<float> t(n, 0.0f);
    if (mat.translucency) {
      for (size_t v = 0; v < n; ++v) {
        const glm::dvec3& P = m.positions[v];
        const glm::dvec3& N = m.normals[v];
        const glm::dvec3 V = model::view_vector(scene.camera, P - view.eye);
        const model::LightSample ls = model::sample_light(light, P, N);
        t[v] =
            static_cast<float>(model::translucency_dot_unsaturated(V, ls.L, N, *mat.translucency));
      }
    }
    s.t_per_light.push_back(std::move(t));
  }
  return s;
}

ObjectSpaceMesh object_space_mesh(const SceneObject& object, const SceneView& view) {
  const glm::dmat4 m = object.transform.matrix();
  const glm::dmat4 to_object = glm::inverse(m);
  const glm::dmat3 a(m), a_transpose = glm::transpose(a);
  ObjectSpaceMesh o;
  for (const glm::dvec3& p : object.mesh.positions)
    o.position.emplace_back(glm::dvec3(to_object * glm::dvec4(p, 1.0)));
  for (const glm::dvec3& n : object.mesh.normals)
    o.normal.emplace_back(glm::normalize(a_transpose * n));
  // Rows of R [A | t - eye] and R A^-T (glm matrices are column-major: row r, column c is
  // [c][r]).
  const glm::dmat3 linear = view.view * a;
  const glm::dvec3 move = view.view * (glm::dvec3(m[3]) - view.eye);
  const glm::dmat3 normal = view.view * glm::transpose(glm::inverse(a));
  for (int r = 0; r < 3; ++r) {
    const auto row = static_cast<size_t>(r);
    for (int c = 0; c < 3; ++c) {
      o.matrices.position[4 * row + static_cast<size_t>(c)] = static_cast<float>(linear[c][r]);
      o.matrices.normal[3 * row + static_cast<size_t>(c)] = static_cast<float>(normal[c][r]);
    }
    o.matrices.position[4 * row + 3] = static_cast<float>(move[r]);
  }
  return o;
}

namespace {

// `data`'s vertices 0..n-1 stored as `storage` says, sent directly or (`indexed`) as indices
// into the attributes' arrays (vertex_quantiser.h index_attributes, what the FIFO log puts in
// MEM1), and read back by the console's vertex loader.
std::vector<LoadedVertex> load_stored(const VertexAttributeData& data, const VertexStorage& storage,
                                      bool indexed, const std::string& origin) {
  const VertexAttributeFormat format = storage_format(storage, data, origin);
  std::vector<u32> order(data.vertex_count());
  for (size_t v = 0; v < order.size(); ++v) order[v] = static_cast<u32>(v);
  const std::vector<AttributeElements> elements = quantise_attributes(data, format);
  std::vector<LoadedVertex> loaded;
  if (indexed) {
    const IndexedArrays arrays = index_attributes(elements, origin);
    const VertexLoader loader(indexed_inputs(arrays), format, origin);
    loaded = loader.load(indexed_vertex_stream(arrays, order), order.size(), arrays.views());
  } else {
    const VertexLoader loader(sent_inputs(data, AttributeInput::Direct), format, origin);
    loaded = loader.load(direct_vertex_stream(elements, order), order.size(), VertexArrays{});
  }
  LT_CHECK(loaded.size() == order.size(), "a stream of ltrender's drops no vertex");
  return loaded;
}

}  // namespace

VertexStream stored_vertex_stream(const Scene& scene, const SceneObject& object,
                                  const SceneView& view, const VertexStorage& storage,
                                  const std::string& origin, bool indexed) {
  const VertexStream f32 = make_vertex_stream(scene, object, view);
  const ObjectSpaceMesh mesh = object_space_mesh(object, view);
  VertexStream s;
  s.object_matrices = mesh.matrices;
  // The attributes every pass shares (the UVs in slot 1, as a GX_TEX_ST slot sends them)...
  VertexAttributeData shared;
  shared.position = mesh.position;
  shared.normal = mesh.normal;
  add_normal_frames(shared);  // sent only where the storage says /nbt
  shared.color[0] = f32.color;
  if (!f32.uv.empty()) shared.texcoord[1] = f32.uv;
  for (const LoadedVertex& v : load_stored(shared, storage, indexed, origin)) {
    s.position.push_back(v.position);
    s.normal.push_back(v.normal[0]);
    s.color.push_back(v.color[0]);
    if (!f32.uv.empty()) s.uv.push_back(v.texcoord[1]);
    s.eye_position.push_back(eye_position(mesh.matrices.position, v.position));
    s.eye_normal.push_back(eye_normal(mesh.matrices.normal, v.normal[0]));
  }
  // ... and each light's t, a GX_TEX_S slot with the fraction its own values allow.
  for (const std::vector<float>& t : f32.t_per_light) {
    VertexAttributeData pass;
    pass.position = mesh.position;
    for (float x : t) pass.texcoord[0].emplace_back(x, 0.0f);
    pass.texcoord_components[0] = 1;
    std::vector<float> stored;
    for (const LoadedVertex& v : load_stored(pass, storage, indexed, origin))
      stored.push_back(v.texcoord[0].x);
    s.t_per_light.push_back(std::move(stored));
  }
  return s;
}

VertexStream object_vertex_stream(const Scene& scene, const SceneObject& object,
                                  const SceneView& view, const GxVariant& variant) {
  if (variant.storage.is_default()) return make_vertex_stream(scene, object, view);
  return stored_vertex_stream(scene, object, view, variant.storage, "--variant",
                              draws_indexed(variant.draw));
}

VertexAttributeData pass_vertex_data(std::span<const glm::vec3> positions,
                                     std::span<const glm::vec3> normals, const VertexStream& stream,
                                     const VertexDescriptor& sent, const TexCoordFormats& formats,
                                     size_t pass) {
  VertexAttributeData d;
  d.position.assign(positions.begin(), positions.end());
  if (sent.has(kVaNrm)) {
    d.normal.assign(normals.begin(), normals.end());
    add_normal_frames(d);  // an NBT's binormal and tangent, sent only where the storage says /nbt
  }
  if (sent.has(kVaClr0)) d.color[0] = stream.color;
  if (sent.has(kVaClr1)) d.color[1] = stream.color;
  const std::vector<float>* t =
      pass < stream.t_per_light.size() ? &stream.t_per_light[pass] : nullptr;
  for (int n = 0; n < kMaxTexGens; ++n) {
    if (!sent.has(kVaTex0 + n)) continue;
    const auto i = static_cast<size_t>(n);
    for (size_t v = 0; v < positions.size(); ++v) {
      if (formats.kind[i] == TexCoordFormats::ST)
        d.texcoord[i].push_back(v < stream.uv.size() ? stream.uv[v] : glm::vec2(0.0f));
      else
        d.texcoord[i].emplace_back(t ? (*t)[v] : 0.0f, 0.0f);
    }
    if (formats.kind[i] != TexCoordFormats::ST) d.texcoord_components[i] = 1;
  }
  return d;
}

std::pair<VertexDescriptor, TexCoordFormats> planned_attributes(const VertexFormatPlan& v) {
  VertexDescriptor sent;
  TexCoordFormats formats;
  const u8 direct = static_cast<u8>(AttributeInput::Direct);
  sent.type[kVaPos] = sent.type[kVaNrm] = direct;
  if (v.colour) sent.type[kVaClr0] = direct;
  if (v.t) {
    sent.type[kVaTex0] = direct;
    formats.kind[0] = TexCoordFormats::S;
  }
  if (v.uv) {
    sent.type[static_cast<size_t>(kVaTex0 + v.uv_attribute())] = direct;
    formats.kind[static_cast<size_t>(v.uv_attribute())] = TexCoordFormats::ST;
  }
  return {sent, formats};
}

namespace {

void keep_smallest(std::optional<int>& smallest, int frac) {
  smallest = smallest ? std::min(*smallest, frac) : frac;
}

}  // namespace

VertexDeclarations storage_declarations(const Scene& scene, const GxVariant& variant,
                                        const ScenePlan& plan) {
  VertexDeclarations out;
  out.storage = variant.storage;
  out.indexed = draws_indexed(variant.draw);
  out.format = variant.vat;
  if (variant.storage.is_default() && !out.indexed) return out;
  const bool stored = !variant.storage.is_default();
  const SceneView view = SceneView::of(scene);
  std::optional<int> position_frac, texcoord_frac;
  for (const SceneObject& o : scene.objects) {
    const auto m = std::find_if(plan.materials.begin(), plan.materials.end(),
                                [&](const MaterialPlan& mp) { return mp.material == o.material; });
    if (m == plan.materials.end()) continue;
    const VertexStream stream = make_vertex_stream(scene, o, view);
    const ObjectSpaceMesh mesh = stored ? object_space_mesh(o, view) : ObjectSpaceMesh{};
    for (size_t p = 0; p < m->passes.size(); ++p) {
      const VertexFormatPlan& v = m->passes[p].vertex;
      const auto [sent, formats] = planned_attributes(v);
      const VertexAttributeData data =
          pass_vertex_data(stored ? mesh.position : stream.position,
                           stored ? mesh.normal : stream.normal, stream, sent, formats, p);
      const VertexAttributeFormat format = storage_format(variant.storage, data, "--variant");
      keep_smallest(position_frac, format.position.frac);
      if (v.t) keep_smallest(texcoord_frac, format.texcoord[0].frac);
      if (v.uv)
        keep_smallest(texcoord_frac, format.texcoord[static_cast<size_t>(v.uv_attribute())].frac);
      if (!out.indexed) continue;
      const IndexedArrays arrays = index_attributes(quantise_attributes(data, format), "--variant");
      for (int a : arrays.arrays) {
        const auto i = static_cast<size_t>(a);
        out.index16[i] = out.index16[i] || arrays.input[i] == AttributeInput::Index16;
      }
    }
  }
  if (out.storage.position.auto_frac && position_frac) out.storage.position.frac = *position_frac;
  if (out.storage.texcoord.auto_frac && texcoord_frac) out.storage.texcoord.frac = *texcoord_frac;
  out.storage.position.auto_frac = out.storage.texcoord.auto_frac = false;
  return out;
}

}  // namespace lt::gx
