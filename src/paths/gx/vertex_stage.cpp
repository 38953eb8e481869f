#include "paths/gx/vertex_stage.h"

#include "image/image.h"
#include "model/translucency.h"

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

void run_vertex_stage(const GxState& state, const VertexStream& stream, size_t light,
                      LightRounding rounding, VertexOutputs& out) {
  const size_t n = stream.position.size();
  out.num_texgens = state.texgen.num_texgens;
  out.colors.resize(n);
  out.texcoords.resize(out.num_texgens > 0 ? n : 0);
  const std::vector<float>* t =
      light < stream.t_per_light.size() ? &stream.t_per_light[light] : nullptr;
  for (size_t v = 0; v < n; ++v) {
    out.colors[v] = light_vertex(state.lighting, stream.eye_position[v], stream.eye_normal[v],
                                 {stream.color[v], stream.color[v]}, rounding);
    if (out.num_texgens == 0) continue;
    TexGenInputs in;
    in.position = stream.position[v];
    in.normal = stream.normal[v];
    const glm::vec2 uv = v < stream.uv.size() ? stream.uv[v] : glm::vec2(0.0f);
    for (int c = 0; c < kMaxTexGens; ++c)
      in.texcoords[static_cast<size_t>(c)] =
          state.texcoord_formats.is_uv(c) ? uv : glm::vec2(t ? (*t)[v] : 0.0f, 0.0f);
    for (int g = 0; g < out.num_texgens; ++g)
      out.texcoords[v][static_cast<size_t>(g)] = generate_texcoord(state.texgen, g, in);
  }
}

}  // namespace lt::gx
