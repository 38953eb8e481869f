#include "paths/combiners/map_stage.h"

#include <cmath>

#include "model/translucency.h"

namespace lt {

glm::dvec3 map_term_gain(const Material& material, const Light& light) {
  const Translucency& tr = *material.translucency;
  return material.albedo * light.color * (light.translucency_scale + tr.ambient) * tr.tint;
}

std::vector<float> map_lut_texels(const model::PowerLut& lut, const Translucency& tr,
                                  const Light& light) {
  const double s = light.translucency_scale, a = tr.ambient;
  std::vector<float> texels(static_cast<size_t>(lut.size), 0.0f);
  if (!(s + a > 0)) return texels;
  for (int i = 0; i < lut.size; ++i) {
    // The same t_i = i / (N - 1) as PowerLut::build, so lut.coordinate(t) samples it.
    const double t = static_cast<double>(i) / (lut.size - 1);
    const double v = (model::lobe(t, tr.power) * s + a) / (s + a);
    texels[static_cast<size_t>(i)] = static_cast<float>(std::round(v * 255.0) / 255.0);
  }
  return texels;
}

}  // namespace lt
