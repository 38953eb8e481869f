// A texture as the GL paths upload it, and GL_LINEAR sampling of it in double: what the
// reference reads a thickness map (and an artist's lobe ramp) with, and what every other path's
// own sampling is judged against.
//
// Orientation: v = 0 is the BOTTOM row of the image, v = 1 the top (OpenGL's convention, and
// the one the UV baker writes maps in). The texels are stored in that order too (row 0 is the
// image's bottom row), which is the order glTexImage2D takes them in, so a GL path uploads
// `texels` as they are.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace lt::model {

// What a coordinate beyond [0, 1] reads (GL_TEXTURE_WRAP_S/T; a glTF sampler's wrapS/wrapT
// names the same three GL enums [glTF 2.0 spec 3.8.4 Samplers]). Thickness maps and ramps are
// always ClampToEdge; an albedo map from a glTF sampler may repeat.
enum class Wrap { ClampToEdge, Repeat, MirroredRepeat };
const char* wrap_name(Wrap wrap);  // "CLAMP_TO_EDGE", "REPEAT", "MIRRORED_REPEAT"

struct Texture {
  int width = 0, height = 0;
  std::vector<float> texels;  // width * height * 3 (rgb), row 0 = bottom row of the image (v = 0)
  Wrap wrap_s = Wrap::ClampToEdge, wrap_t = Wrap::ClampToEdge;

  glm::dvec3 texel(int x, int y) const {
    const float* t = &texels[(static_cast<size_t>(y) * width + x) * 3];
    return {t[0], t[1], t[2]};
  }
};

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
