// The table a combiners lobe pass samples on texture unit 0 (`texture power_lut` in the .comb
// files), in 8 bits as GL 1.3 hardware stores it: the power LUT of t^p, or a material's lobe ramp
// (docs/maps.md "Thickness maps and lobe ramps"), and the coordinate that samples t on it.
//
//  - t^p: kCombinerLutSize texels at t_i = i / (N - 1), luminance, read at the texel-centre
//    remap u = t (N - 1)/N + 0.5/N (model/power_lut.h).
//  - A ramp: the ramp's own texels, rgb (luminance for a grey ramp), read at u = t: GL_LINEAR
//    between texel centres and CLAMP_TO_EDGE beyond them is what the reference's sample_ramp
//    computes, so the table adds only its 8-bit rounding (none for an 8-bit ramp file). The
//    per-vertex t is interpolated unsaturated; the clamp saturates it per pixel.
//
// A texel holds at most 1: a float ramp brighter than that is stored divided by its gain (its
// largest value), which the pass multiplies back into its constant colour (lobe_gain).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "gl/gl.h"
#include "scene/scene.h"

namespace lt {

// The power LUT size of the t^p table (8-bit texels, as GL 1.3 hardware stores them).
inline constexpr int kCombinerLutSize = 256;

struct LobeTable {
  int width = 0;
  int channels = 1;              // 1: GL_LUMINANCE8 (t^p, a grey ramp); 3: GL_RGB8 (an rgb ramp)
  std::vector<float> texels;     // width * channels values, each a multiple of 1/255 in [0, 1]
  double scale = 1, offset = 0;  // u = t * scale + offset

  double coordinate(double t) const { return t * scale + offset; }
};

// 1 for t^p; a ramp's largest texel value when it is above 1 (a float ramp), else 1.
double lobe_gain(const Translucency& tr);

// The lobe / lobe_gain at every texel: what lobe_vertex.comb and lobe_texgen.comb sample.
LobeTable lobe_table(const Translucency& tr);

// A thickness map's pass (map_stage.h): (lobe s + a) / (gain s + a) at every texel, for `light`'s
// s; the map multiplies the whole term, the ambient a included, so a rides in the table. All 0
// where gain s + a = 0 (the term is 0).
LobeTable map_lobe_table(const Translucency& tr, const Light& light);

// The table as a GL_TEXTURE_1D (GL_LINEAR, CLAMP_TO_EDGE), its texels uploaded as bytes so GL
// rounds nothing of its own. Needs a current context; the caller owns the texture.
GLuint upload_lobe_table(const LobeTable& table);

}  // namespace lt
