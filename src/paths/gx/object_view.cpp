#include "paths/gx/object_view.h"

#include <limits>

#include "model/translucency.h"

namespace lt::gx {

glm::dvec3 material_centre(const Scene& scene, int material) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-lo);
  for (const SceneObject& o : scene.objects) {
    if (o.material != material) continue;
    for (const glm::dvec3& p : o.mesh.positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  if (lo.x > hi.x) return glm::dvec3(0);  // no vertex: nothing is drawn, any centre will do
  return (lo + hi) * 0.5;
}

ConstantView constant_view(const Scene& scene, const GxVariant& variant, const glm::dvec3& centre,
                           const Light& light) {
  if (!variant.view_object) return {-scene.camera.forward(), -light.direction, 1.0};
  const glm::dvec3 V = model::view_vector(scene.camera, centre - scene.camera.eye);
  // A point light at the centre lights it head-on from the eye's side (L = V).
  const model::LightSample ls = model::sample_light(light, centre, V);
  return {V, ls.L, ls.attenuation};
}

}  // namespace lt::gx
