#include "paths/combiners/cube_lobe.h"

#include <algorithm>
#include <vector>

#include "gl/map_texture.h"
#include "image/image.h"
#include "model/translucency.h"

namespace lt {

namespace {

// The direction of texel (i, j) of a cube face, from GL's face table (spec "Cube Map Texture
// Selection": s = (sc/|ma| + 1)/2, t = (tc/|ma| + 1)/2), at the texel centre.
glm::dvec3 cube_direction(int face, int i, int j, int size) {
  const double sc = 2.0 * (i + 0.5) / size - 1, tc = 2.0 * (j + 0.5) / size - 1;
  switch (face) {
    case 0:
      return {1, -tc, -sc};  // +X
    case 1:
      return {-1, -tc, sc};  // -X
    case 2:
      return {sc, 1, tc};  // +Y
    case 3:
      return {sc, -1, -tc};  // -Y
    case 4:
      return {sc, -tc, 1};  // +Z
    default:
      return {-sc, -tc, -1};  // -Z
  }
}

// The view vector the cube is built for: exact for an orthographic camera; under perspective
// the direction to the centre of the objects drawn with this material.
glm::dvec3 cube_view(const Scene& s, const glm::dvec3& eye, int material) {
  if (s.camera.projection == Camera::Projection::Orthographic) return -s.camera.forward();
  glm::dvec3 sum(0);
  size_t n = 0;
  for (const SceneObject& o : s.objects) {
    if (o.material != material) continue;
    for (const glm::dvec3& p : o.mesh.positions) sum += p - eye;
    n += o.mesh.positions.size();
  }
  return model::view_vector(s.camera, n ? sum / static_cast<double>(n) : glm::dvec3(0));
}

}  // namespace

CubeLobe build_cube_lobe(const Scene& s, const glm::dvec3& eye, int material, size_t light_index,
                         bool full) {
  const Material& mat = s.materials[static_cast<size_t>(material)];
  const Translucency& tr = *mat.translucency;
  const Light& light = s.lights[light_index];
  const glm::dmat3 view(s.camera.view_from_origin());  // world -> eye rotation
  const glm::dmat3 to_world = glm::transpose(view);
  const glm::dvec3 V = cube_view(s, eye, material);
  const glm::dvec3 L = -light.direction;
  const int n = kCombinerCubeSize;
  std::vector<glm::dvec3> rgb(6 * static_cast<size_t>(n) * n);
  std::vector<double> g(rgb.size());
  double g_max = 0;
  // The scene's ambient light goes with the first pass (light 0).
  const glm::dvec3 ambient = light_index == 0 ? mat.albedo * s.ambient_light : glm::dvec3(0);
  const glm::dvec3 T = model::thickness(tr, glm::dvec3(1));  // constant when `full`
  for (int f = 0; f < 6; ++f) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const size_t k = (static_cast<size_t>(f) * n + j) * n + i;
        const glm::dvec3 N = glm::normalize(to_world * cube_direction(f, i, j, n));
        // a + s * lobe, rgb for a ramp (model::material_lobe: t^p, or the ramp at t).
        const glm::dvec3 term =
            tr.ambient + light.translucency_scale *
                             model::material_lobe(tr, model::translucency_dot(V, L, N, tr));
        const double diffuse = std::max(glm::dot(N, L), 0.0);
        if (full) {
          rgb[k] = mat.albedo * light.color * (diffuse + term * T) + ambient;
          g[k] = 1;  // alpha unused
        } else {
          // One channel: t^p's or a grey ramp's (plan_combiners gives an rgb ramp t=vertex).
          rgb[k] = mat.albedo * light.color * diffuse + ambient;
          g[k] = term.r;
        }
        g_max = std::max(g_max, g[k]);
      }
    }
  }
  // g_max = 0 (no lobe and no translucency ambient): alpha 0 and constant 0 either way.
  const double scale = g_max > 0 ? g_max : 1.0;
  CubeLobe c;
  c.lobe_color = mat.albedo * light.color * scale;
  c.constant_clamped = !full && std::max({c.lobe_color.r, c.lobe_color.g, c.lobe_color.b}) > 4;
  std::vector<unsigned char> texels(static_cast<size_t>(n) * n * 4);
  glGenTextures(1, &c.texture);
  glBindTexture(GL_TEXTURE_CUBE_MAP, c.texture);
  for (int f = 0; f < 6; ++f) {
    for (size_t t = 0; t < static_cast<size_t>(n) * n; ++t) {
      const size_t k = static_cast<size_t>(f) * n * n + t;
      // rgb over 1 is lossless to clamp: the pixel saturates anyway (every other term >= 0).
      for (int ch = 0; ch < 3; ++ch) texels[t * 4 + ch] = to_unorm8(rgb[k][ch]);
      texels[t * 4 + 3] = to_unorm8(g[k] / scale);
    }
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + f), 0, GL_RGBA8, n, n, 0,
                 GL_RGBA, GL_UNSIGNED_BYTE, texels.data());
  }
  gl::set_linear_clamp_to_edge(GL_TEXTURE_CUBE_MAP);
  glBindTexture(GL_TEXTURE_CUBE_MAP, 0);
  return c;
}

}  // namespace lt
