#include "scene/default_lights.h"

#include <nlohmann/json.hpp>

namespace lt {

namespace {

std::string direction_text(const glm::dvec3& d) {
  // Three decimals: a description, not a value to read back.
  auto r = [](double x) { return std::round(x * 1000) / 1000 + 0.0; };
  return nlohmann::json({r(d.x), r(d.y), r(d.z)}).dump();
}

}  // namespace

bool renders_unlit(const Scene& scene) {
  return scene.lights.empty() && scene.ambient_light == glm::dvec3(0);
}

std::string add_default_lights(Scene& scene) {
  // The camera's frame: forward into the view, up made orthogonal to it (a camera's `up` need
  // only not be parallel to the view), right.
  const glm::dvec3 forward = scene.camera.forward();
  const glm::dvec3 up =
      glm::normalize(scene.camera.up - glm::dot(scene.camera.up, forward) * forward);
  const glm::dvec3 right = glm::cross(forward, up);

  Light back;
  back.type = Light::Type::Directional;
  // Travelling towards the camera (-forward) and down: it comes from behind and above.
  back.direction = glm::normalize(-forward - kBackLightRise * up);
  Light fill;
  fill.type = Light::Type::Directional;
  // From the camera's side, up and to the left: travelling forward, down and right.
  fill.direction = glm::normalize(forward - 0.5 * up + 0.5 * right);
  fill.color = glm::dvec3(kFillIntensity);
  scene.lights.push_back(back);
  scene.lights.push_back(fill);
  return "the default rig: a back light travelling " + direction_text(back.direction) +
         " (towards the camera, from behind the object) and a fill at " +
         nlohmann::json(kFillIntensity).dump() + " travelling " + direction_text(fill.direction) +
         " (from up-left of the camera)";
}

}  // namespace lt
