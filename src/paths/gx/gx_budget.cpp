#include "paths/gx/gx_budget.h"

#include "paths/gx/gx_path.h"

namespace lt::gx {

budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile) {
  const GxVariant v = parse_gx_variant(variant.empty() ? "t=vertex" : variant);
  const ScenePrograms programs = scene_programs_for(scene, v, "");
  std::vector<std::string> names;
  for (const Material& m : scene.materials) names.push_back(m.name);
  budget::Report r = gx_programs_report(programs.by_material, names, profile);
  r.file = scene.file.string();
  r.input = "scene";
  r.variant = to_string(v);
  return r;
}

}  // namespace lt::gx
