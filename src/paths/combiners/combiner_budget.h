// Stage budgets for the combiners path (`ltrender budget SCENE --path combiners --profile P`):
// what the programs the path builds for a scene use (combiner stages, texture units, passes,
// constant colours, lights), against what a class of hardware has. No GL context needed.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"

namespace lt {

struct CombinerBudgetProfile {
  std::string name;         // as given to --profile
  std::string summary;      // the hardware it stands for
  int stages = 0;           // combiner stages (texture environments / TEV stages)
  int texture_units = 0;    // texture units
  int constant_colors = 0;  // one TEXTURE_ENV_COLOR per unit
  int lights = 0;           // hardware lights per pass (GL_MAX_LIGHTS)
};

// gl13-2units, gl13-3units, gl-8units (the Wii's wii-tev is the gx path's, gx_budget.h).
const std::vector<CombinerBudgetProfile>& combiner_budget_profiles();

struct CombinerBudgetMaterial {
  std::string material, program;  // program: file(s) in combiners/, "+"-separated
  int stages = 0, texture_units = 0, constant_colors = 0, passes = 0;
};

struct CombinerBudgetReport {
  CombinerBudgetProfile profile;
  std::string variant;
  std::vector<CombinerBudgetMaterial> materials;  // only materials some object uses
  // The worst material per figure (a pass is one program, so limits apply per material), and
  // the passes of the whole frame (the most any material needs: passes run scene-wide).
  int stages = 0, texture_units = 0, constant_colors = 0, passes = 0, lights = 0;
  std::vector<std::string> over;  // one line per exceeded limit, empty when it fits

  bool fits() const { return over.empty(); }
};

// Throws InputError("--profile", profile, ...) naming the valid profiles for an unknown one.
// `variant` is a combiners variant ("" = the default).
CombinerBudgetReport combiner_budget(const Scene& scene, const std::string& profile,
                                     const std::string& variant = "");

// `ltrender budget FILE.comb`: one hand-written combiner program (combiners/README.md) as one
// pass against the profile. Throws InputError naming the file and line for a bad program.
CombinerBudgetReport combiner_budget_file(const std::string& file, const std::string& profile);

// Human-readable table and one JSON object (for --json).
std::string to_text(const CombinerBudgetReport& report);
std::string to_json(const CombinerBudgetReport& report);

}  // namespace lt
