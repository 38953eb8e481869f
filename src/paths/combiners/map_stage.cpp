#include "paths/combiners/map_stage.h"

#include "paths/combiners/lobe_table.h"

namespace lt {

glm::dvec3 map_term_gain(const Material& material, const Light& light) {
  const Translucency& tr = *material.translucency;
  return material.albedo * light.color * (lobe_gain(tr) * light.translucency_scale + tr.ambient) *
         tr.tint;
}

}  // namespace lt
