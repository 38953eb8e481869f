// The combiners path's thickness-map pass (combiners/lobe_vertex_map.comb): the numbers a
// material with a map needs beside its program. The map multiplies the whole translucency term,
// (lobe s + a) att T, so the ambient a moves from the secondary colour into the lobe's table, per
// light: texel = (lobe s + a) / (gain s + a) (lobe_table.h's map_lobe_table; gain = 1 but for a
// float ramp brighter than 1), and K = albedo * color * (gain s + a) * tint goes into the primary
// colour as att * K / g, g = fit_scale(max K) the stage's rgb_scale (exact while att * K / g <= 1,
// i.e. K <= 4 with att <= 1).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace lt {

inline bool samples_thickness_map(const Material& m) {
  return m.translucency && m.translucency->thickness_source == ThicknessSource::Texture;
}

// K for `light`: what the map pass must multiply the map and the table by.
glm::dvec3 map_term_gain(const Material& material, const Light& light);

}  // namespace lt
