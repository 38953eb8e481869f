#include "budget/combiner_program_budget.h"

#include <algorithm>

#include "core/error.h"
#include "core/fs.h"

namespace lt {

const std::vector<CombinerBudgetProfile>& combiner_budget_profiles() {
  static const std::vector<CombinerBudgetProfile> profiles = {
      // GeForce2 (NV15): 2 texture units, register combiners exposed as 2 env stages.
      {"gl13-2units", "GeForce2-class: 2 texture units = 2 combiner stages", 2, 2, 2, 8},
      // Radeon 7500 (R100): 3 texture units.
      {"gl13-3units", "Radeon 7500-class: 3 texture units = 3 combiner stages", 3, 3, 3, 8},
      // What Mesa (llvmpipe) exposes to fixed-function GL: GL_MAX_TEXTURE_UNITS = 8.
      {"gl-8units", "Mesa llvmpipe fixed function: 8 texture units", 8, 8, 8, 8},
  };
  return profiles;
}

const CombinerBudgetProfile& combiner_budget_profile(const std::string& given) {
  const std::string profile = given.empty() ? "gl13-2units" : given;
  const auto& profiles = combiner_budget_profiles();
  const auto it = std::find_if(profiles.begin(), profiles.end(),
                               [&](const CombinerBudgetProfile& p) { return p.name == profile; });
  if (it == profiles.end()) {
    std::string names;
    for (const auto& p : profiles) names += (names.empty() ? "" : ", ") + p.name;
    // The Wii is not GL 1.3 state: its profile belongs to the gx path, which counts a real TEV.
    const std::string hint = profile == "wii-tev" ? "; wii-tev is the gx path's (--path gx)" : "";
    throw InputError("--profile", profile,
                     "unknown combiner profile (valid: " + names + ")" + hint);
  }
  return *it;
}

// GL 1.3 runs stage N on unit N and skips a unit with texturing off, so every stage costs a
// unit; the colour sum after the combiners is free. A material's row holds the largest of its
// programs.
void add_combiner_program(budget::Item& item, const combiners::CombinerProgram& program) {
  const int program_stages = static_cast<int>(program.stages.size());
  for (budget::Resource& r : item.resources) {
    if (r.key == "stages" || r.key == "texture_units") r.used = std::max(r.used, program_stages);
    if (r.key == "constant_colors") r.used = std::max(r.used, program.constant_colors());
  }
}

budget::Item combiner_budget_row(budget::Scope scope, const std::string& name,
                                 const CombinerBudgetProfile& p) {
  budget::Item item;
  item.scope = scope;
  item.name = name;
  item.profile = p.name;
  item.resources = {{"stages", "stages", 0, p.stages, "", {}},
                    {"texture_units", "texture units", 0, p.texture_units, "", {}},
                    {"constant_colors", "constant colours", 0, p.constant_colors, "", {}}};
  return item;
}

budget::Report combiner_budget_report(const std::string& file, const std::string& input,
                                      const CombinerBudgetProfile& p) {
  budget::Report r;
  r.file = file;
  r.input = input;
  r.path = "combiners";
  r.profiles = {{p.name, "", p.summary}};
  return r;
}

budget::Report combiner_budget_file(const std::string& file, const std::string& profile) {
  const CombinerBudgetProfile& p = combiner_budget_profile(profile);
  budget::Report r = combiner_budget_report(file, "program", p);
  const combiners::CombinerProgram program =
      combiners::parse_combiner_program(read_input_file(file, InputKind::Program), file);
  budget::Item item = combiner_budget_row(budget::Scope::Program, "program " + program.name, p);
  item.program = file;
  add_combiner_program(item, program);
  item.resources.push_back({"passes", "passes", 1, {}, "one file is one pass's state", {}});
  r.items.push_back(std::move(item));
  return r;
}

}  // namespace lt
