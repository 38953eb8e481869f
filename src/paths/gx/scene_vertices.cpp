#include "paths/gx/scene_vertices.h"

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

}  // namespace lt::gx
