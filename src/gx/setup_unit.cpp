#include "gx/setup_unit.h"

namespace lt::gx {

void TriangleCounts::add(const TriangleCounts& o) {
  submitted += o.submitted;
  rejected += o.rejected;
  culled += o.culled;
  clipped_away += o.clipped_away;
  set_up += o.set_up;
}

void make_raster_vertices(const std::vector<glm::vec4>& clip, const VertexOutputs& outputs,
                          const std::array<TexCoordScale, kMaxTexGens>& scales,
                          std::vector<RasterVertex>& out) {
  out.resize(clip.size());
  for (size_t v = 0; v < clip.size(); ++v) {
    RasterVertex& r = out[v];
    r.clip = clip[v];
    r.color = outputs.colors[v];
    for (int g = 0; g < outputs.num_texgens; ++g) {
      const size_t gi = static_cast<size_t>(g);
      const glm::vec3& stq = outputs.texcoords[v][gi];
      const float ss = scales[gi].s ? static_cast<float>(scales[gi].s) : 1.0f;
      const float ts = scales[gi].t ? static_cast<float>(scales[gi].t) : 1.0f;
      r.tex[gi] = {stq.x * ss, stq.y * ts, stq.z};
    }
  }
}

void setup_triangles(const std::vector<RasterVertex>& vertices,
                     const std::vector<glm::uvec3>& triangles, size_t first, size_t last,
                     const GxState& state, const Viewport& viewport, const Scissor& scissor,
                     CoverageRule rule, std::vector<Triangle>& out, TriangleCounts& counts) {
  ClippedTriangles clipped;
  Triangle t;
  for (size_t i = first; i < last; ++i) {
    const glm::uvec3& tri = triangles[i];
    ++counts.submitted;
    switch (clip_triangle(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]], state.cull_mode,
                          viewport, clipped)) {
      case TriangleFate::Rejected:
        ++counts.rejected;
        continue;
      case TriangleFate::Culled:
        ++counts.culled;
        continue;
      case TriangleFate::ClippedAway:
        ++counts.clipped_away;
        continue;
      case TriangleFate::Drawn:
        break;
    }
    for (int k = 0; k < clipped.count; ++k) {
      const auto& idx = clipped.triangles[static_cast<size_t>(k)];
      if (!setup_triangle(clipped.vertices[idx[0]], clipped.vertices[idx[1]],
                          clipped.vertices[idx[2]], state.lighting.num_channels,
                          state.texgen.num_texgens, scissor, t, rule))
        continue;
      out.push_back(t);
      ++counts.set_up;
    }
  }
}

}  // namespace lt::gx
