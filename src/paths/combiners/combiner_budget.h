// Stage budgets for the combiners path (`ltrender budget SCENE --path combiners --profile P`):
// what the programs the path builds for a scene use (combiner stages, texture units, passes,
// constant colours, lights), against what a class of hardware has. No GL context needed.
#pragma once

#include <string>
#include <vector>

#include "paths/budget/report.h"
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

// One row (scope material) per material some object uses: the stages, texture units and
// constant colours of the largest program it draws with (a pass is one program, so the limits
// apply per program), the scene's lights (a port hands per-vertex lighting to the hardware
// lights) and its passes (multipass: no limit). Throws InputError("--profile", profile, ...)
// naming the valid profiles for an unknown one. `variant` is a combiners variant ("" = the
// default); `profile` "" is gl13-2units.
budget::Report combiner_budget(const Scene& scene, const std::string& profile,
                               const std::string& variant = "");

// `ltrender budget FILE.comb`: one hand-written combiner program (combiners/README.md) as one
// pass against the profile (one row, scope program). Throws InputError naming the file and
// line for a bad program.
budget::Report combiner_budget_file(const std::string& file, const std::string& profile);

}  // namespace lt
