#include "paths/gx/generator.h"

#include "core/error.h"
#include "paths/gx/pass_plan_parts.h"

namespace lt::gx {

SceneView SceneView::of(const Scene& scene) {
  SceneView v;
  v.eye = scene.camera.eye;
  // The same view as gl::SceneGeometry, so every path sees one camera.
  v.view = glm::dmat3(scene.camera.view_from_origin());
  return v;
}

ScenePlan plan_scene(const Scene& scene, const GxVariant& variant) {
  const std::string why = refusal(scene, variant);
  if (!why.empty()) throw InputError("--variant", to_string(variant), "gx: " + why);
  return PassPlanner(scene, variant).plan();
}

GeneratedPrograms generate_programs(const Scene& scene, const GxVariant& variant) {
  return emit_programs(plan_scene(scene, variant));
}

}  // namespace lt::gx
