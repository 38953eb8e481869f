#include "gx/vertex_stage.h"

namespace lt::gx {

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
