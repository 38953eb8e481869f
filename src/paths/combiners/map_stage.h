// The combiners path's thickness-map pass (combiners/lobe_vertex_map.comb): the numbers a
// material with a map needs beside its program. The map multiplies the whole translucency term,
// (t^p s + a) att T, so the ambient a moves from the secondary colour into the LUT, per light:
// texel i = (t_i^p s + a) / (s + a), and the gain K = albedo * color * (s + a) * tint goes into
// the primary colour as att * K / g, g = fit_scale(max K) the stage's rgb_scale (exact while
// att * K / g <= 1, i.e. K <= 4 with att <= 1).
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "model/power_lut.h"
#include "scene/scene.h"

namespace lt {

inline bool samples_thickness_map(const Material& m) {
  return m.translucency && m.translucency->thickness_source == ThicknessSource::Texture;
}

// K for `light`: what the map pass must multiply the map and the LUT by.
glm::dvec3 map_term_gain(const Material& material, const Light& light);

// The 8-bit texels (t^p s + a) / (s + a) at the texel centres of `lut` (the material's power
// LUT: same size and addressing), rounded to 1/255 once; all 0 where s + a = 0 (the term is 0).
std::vector<float> map_lut_texels(const model::PowerLut& lut, const Translucency& tr,
                                  const Light& light);

}  // namespace lt
