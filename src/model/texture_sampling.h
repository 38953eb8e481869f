// GL_LINEAR sampling in double of a texture as the GL paths upload it (scene/texture_map.h, which
// gives its orientation: v = 0 is the image's bottom row): what the reference reads a thickness
// map (and an artist's lobe ramp) with, and what every other path's own sampling is judged
// against.
#pragma once

#include <glm/glm.hpp>

#include "scene/texture_map.h"

namespace lt::model {

// The texture's data and wrap modes are the scene's (scene/texture_map.h); the names here are
// the ones the model and the paths use.
using Wrap = TextureWrap;
using Texture = lt::Texture;
const char* wrap_name(Wrap wrap);  // "CLAMP_TO_EDGE", "REPEAT", "MIRRORED_REPEAT"

// The four texels and two weights of GL_LINEAR at (u, v): texel i's centre is at
// u = (i + 0.5) / W, so the texel-space position is x = u W - 0.5 (likewise y = v H - 0.5).
// CLAMP_TO_EDGE clamps x to [0, W - 1] (the edge texel is repeated beyond its centre, which is
// what its clamp of the coordinates to [1/2W, 1 - 1/2W] does). REPEAT and MIRRORED_REPEAT take
// i0 = floor(x), i1 = i0 + 1 and the weight frac(x), then wrap each index into [0, W - 1]:
// modulo W, or mirrored over a period of 2W (index -1 reads texel 0, index W texel W - 1)
// [GL 2.1 spec 3.8.7 "Texture Wrap Modes", 3.8.8 "Texture Minification"].
struct BilinearTaps {
  int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  double fx = 0, fy = 0;  // weight of x1 (of y1); x0's is 1 - fx
};
BilinearTaps bilinear_taps(int width, int height, glm::dvec2 uv, Wrap wrap_s = Wrap::ClampToEdge,
                           Wrap wrap_t = Wrap::ClampToEdge);

// GL_LINEAR with the texture's wrap modes, in double:
// (1-fy)((1-fx) t00 + fx t10) + fy((1-fx) t01 + fx t11).
// A NaN coordinate samples texel (0, 0) (never a NaN out: the G-buffer of an uncovered pixel).
glm::dvec3 sample_bilinear(const Texture& texture, glm::dvec2 uv);

// An artist's lobe ramp (a W x 1 texture) at t: sample_bilinear at (t, 0.5), so t = 0 and t = 1
// lie half a texel beyond the first and last centres and take those texels (clamped), as a
// shader's texture2D(ramp, vec2(t, 0.5)) does.
glm::dvec3 sample_ramp(const Texture& ramp, double t);

}  // namespace lt::model
