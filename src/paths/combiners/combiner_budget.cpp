#include "paths/combiners/combiner_budget.h"

#include "paths/combiners/combiners_path.h"

namespace lt {

budget::Report combiner_budget(const Scene& scene, const std::string& profile,
                               const std::string& variant) {
  const CombinerBudgetProfile& p = combiner_budget_profile(profile);
  budget::Report r = combiner_budget_report(scene.file.string(), "scene", p);
  const CombinersVariant v = parse_combiners_variant(variant);  // an unknown name throws
  r.variant = variant.empty() ? "t=vertex" : variant;
  for (const CombinerMaterialPlan& plan : plan_combiners(scene, v)) {
    if (!plan.used) continue;
    const std::string& material = scene.materials[plan.material].name;
    budget::Item item = combiner_budget_row(budget::Scope::Material, "material " + material, p);
    item.material = material;
    for (const auto& [kind, program] : plan.programs) {
      item.program +=
          std::string(item.program.empty() ? "" : "+") + "combiners/" + program_file(kind);
      add_combiner_program(item, program);
    }
    // Per-vertex lighting runs on the CPU here, but a port would hand it to the hardware lights.
    item.resources.push_back(
        {"lights", "lights", static_cast<int>(scene.lights.size()), p.lights, "", {}});
    item.resources.push_back({"passes", "passes", plan.passes(), {}, "", {}});
    item.note = "passes: multipass, no limit";
    r.items.push_back(std::move(item));
  }
  return r;
}

}  // namespace lt
