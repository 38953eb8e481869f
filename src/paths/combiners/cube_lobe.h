// The combiners path's lobe=cube variant: the whole term of one directional light as a cube map
// of the normal, built on the CPU in double (texgen NORMAL_MAP looks it up per pixel). Exact
// where the view is: under an orthographic camera.
#pragma once

#include <glm/glm.hpp>

#include "gl/gl.h"
#include "scene/scene.h"

namespace lt {

// Texels per cube face edge of the lobe=cube variant (8-bit RGBA).
inline constexpr int kCombinerCubeSize = 256;

struct CubeLobe {
  GLuint texture = 0;        // GL_TEXTURE_CUBE_MAP, owned by the caller
  glm::dvec3 lobe_color{0};  // albedo * color * g: the alpha channel holds (a + s lobe) / g
  bool constant_clamped = false;
};

// The whole term of directional light `pass` for `material` as a function of the normal, in
// eye space (texgen NORMAL_MAP gives the eye-space normal). lobe_cube.comb: rgb = albedo *
// color * max(N.L, 0) (+ albedo * ambient_light in pass 0), alpha = (a + s * lobe) / g, T from
// the primary colour. lobe_cube_full.comb (constant T): rgb = the whole term, alpha 1. The lobe
// is the material's (model::material_lobe): t^p or its ramp, which the alpha holds one channel
// of (the red: lobe_cube.comb is planned for grey lobes only).
// `eye`: what positions are relative to; light 0's pass also carries the ambient light; `full`:
// the lobe_cube_full.comb form (constant thickness). Needs a current GL context.
CubeLobe build_cube_lobe(const Scene& scene, const glm::dvec3& eye, int material,
                         size_t light_index, bool full);

}  // namespace lt
