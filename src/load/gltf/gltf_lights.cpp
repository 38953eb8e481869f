#include "load/gltf/gltf_lights.h"

#include <algorithm>
#include <cmath>

#include "scene/scene_limits.h"

namespace lt::gltf {

namespace {
using json = nlohmann::json;

double window(double d, double range) {
  return std::clamp(1 - std::pow(d / range, 4), 0.0, 1.0);
}
}  // namespace

RangeFit fit_range_falloff(double range) {
  RangeFit fit;
  fit.kc = 0, fit.kl = 0;
  fit.kq = 1 / 0.8;  // 1 / mean(window) = 1 / (1 - 1/5)
  constexpr int kSamples = 1000;
  double sum_sq = 0;
  for (int i = 0; i <= kSamples; ++i) {
    const double d = range * i / kSamples;
    const double err = std::abs(1 / fit.kq - window(d, range));
    sum_sq += err * err;
    if (err > fit.max_window_error) {
      fit.max_window_error = err;
      fit.at_distance = d / range;
    }
  }
  fit.rms_window_error = std::sqrt(sum_sq / (kSamples + 1));
  return fit;
}

Light map_light(const Document& doc, int index, const glm::dmat4& world, Notes& notes) {
  const std::string file = doc.path.string();
  const std::string ptr = "/extensions/KHR_lights_punctual/lights/" + std::to_string(index);
  const json& j = at_pointer(doc.json, ptr);
  if (!j.is_object()) doc.fail(ptr, "no such light");
  const std::string type = j.value("type", std::string());
  if (type == "spot")
    doc.fail(ptr + "/type", "spot lights are not modelled yet (directional and point are)");
  if (type != "directional" && type != "point")
    doc.fail(ptr + "/type", "must be \"directional\", \"point\" or \"spot\"");
  Light light;
  const double intensity =
      bounded_number(j, "intensity", 1, 0, kMaxColour / kPhotometricToScene, file, ptr);
  const glm::dvec3 colour = [&] {
    const auto c = bounded_numbers(j, "color", 3, {1, 1, 1}, 0, 1, file, ptr);
    return glm::dvec3(c[0], c[1], c[2]);
  }();
  light.color = colour * (intensity * kPhotometricToScene);
  const json& extras =
      j.contains("extras") && j["extras"].is_object() && j["extras"].contains("ltrender")
          ? j["extras"]["ltrender"]
          : json();
  if (!extras.is_null()) {
    for (auto it = extras.begin(); it != extras.end(); ++it) {
      if (it.key() != "scale")
        doc.fail(ptr + "/extras/ltrender/" + it.key(), "unknown key (scale)");
    }
    light.translucency_scale =
        bounded_number(extras, "scale", 1, 0, kMaxColour, file, ptr + "/extras/ltrender");
  }
  std::string mapped = "mapped " + ptr + " (" + type + ", intensity " + json(intensity).dump() +
                       (type == "directional" ? " lux" : " cd") + ") -> colour " +
                       json({light.color.x, light.color.y, light.color.z}).dump() +
                       " (intensity / pi), translucency scale " +
                       json(light.translucency_scale).dump();
  if (type == "directional") {
    light.type = Light::Type::Directional;
    const glm::dvec3 d = glm::dvec3(world * glm::dvec4(0, 0, -1, 0));
    if (!(glm::length(d) > 0))
      doc.fail(ptr, "its node's transform collapses the light's direction");
    light.direction = glm::normalize(d);
  } else {
    light.type = Light::Type::Point;
    light.position = glm::dvec3(world * glm::dvec4(0, 0, 0, 1));
    if (j.contains("range")) {
      const double range = bounded_number(j, "range", 0, 0, kMaxCoordinate, file, ptr);
      if (!(range > 0)) doc.fail(ptr + "/range", "must be > 0");
      const RangeFit fit = fit_range_falloff(range);
      light.kc = std::min(fit.kc, kMaxAttenuation);
      light.kl = std::min(fit.kl, kMaxAttenuation);
      light.kq = std::min(fit.kq, kMaxAttenuation);
      mapped += ", range " + json(range).dump() + " -> kc " + json(light.kc).dump() + " kl " +
                json(light.kl).dump() + " kq " + json(light.kq).dump() + " (window error: rms " +
                json(fit.rms_window_error).dump() + ", max " + json(fit.max_window_error).dump() +
                " at " + json(fit.at_distance).dump() + " x range)";
    } else {
      light.kc = 0, light.kl = 0, light.kq = 1;
      mapped += ", no range -> inverse square (kc 0, kl 0, kq 1)";
    }
  }
  notes.push_back(mapped);
  note_unmapped_keys(j, ptr, {"type", "intensity", "color", "range"}, "not part of the term",
                     notes);
  return light;
}

}  // namespace lt::gltf
