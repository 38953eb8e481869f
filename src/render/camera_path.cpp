#include "render/camera_path.h"

#include <glm/gtc/matrix_transform.hpp>

namespace lt {

namespace {

glm::dvec3 rotated(const glm::dvec3& v, const glm::dvec3& axis, double degrees) {
  return glm::dvec3(glm::rotate(glm::dmat4(1), glm::radians(degrees), axis) * glm::dvec4(v, 0));
}

}  // namespace

double rounded_to_float(double v) {
  volatile float f = static_cast<float>(v);
  return f;
}

glm::dvec3 rounded_to_float(const glm::dvec3& v) {
  return {rounded_to_float(v.x), rounded_to_float(v.y), rounded_to_float(v.z)};
}

Scene scene_on_camera_path(const Scene& base, int k, int frames) {
  if (k == 0) return base;  // as it is, to the bit: a one-frame sweep is the bench's frame
  Scene s = base;
  const double t = frames > 1 ? k / double(frames - 1) : 0.0;
  const glm::dvec3 up = glm::normalize(base.camera.up);
  s.camera.eye = rounded_to_float(base.camera.target +
                                  rotated(base.camera.eye - base.camera.target, up, 70 * t));
  for (Light& l : s.lights) {
    l.color = rounded_to_float(l.color * (1 + 0.6 * t));
    l.translucency_scale = rounded_to_float(l.translucency_scale * (1 + 0.5 * t));
    if (l.type == Light::Type::Point) {
      l.position = rounded_to_float(base.camera.target +
                                    rotated(l.position - base.camera.target, up, -50 * t));
    } else {
      l.direction = rounded_to_float(rotated(l.direction, up, -50 * t));
    }
  }
  return s;
}

}  // namespace lt
