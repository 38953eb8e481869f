// Stage budgets for the combiners path (`ltrender budget SCENE --path combiners --profile P`):
// what the programs the path builds for a scene use (combiner stages, texture units, passes,
// constant colours, lights), against what a class of hardware has, in the rows of
// budget/combiner_program_budget.h. No GL context needed.
#pragma once

#include <string>

#include "budget/combiner_program_budget.h"
#include "scene/scene.h"

namespace lt {

// One row (scope material) per material some object uses: the stages, texture units and
// constant colours of the largest program it draws with (a pass is one program, so the limits
// apply per program), the scene's lights (a port hands per-vertex lighting to the hardware
// lights) and its passes (multipass: no limit). Throws InputError("--profile", profile, ...)
// naming the valid profiles for an unknown one. `variant` is a combiners variant ("" = the
// default); `profile` "" is gl13-2units.
budget::Report combiner_budget(const Scene& scene, const std::string& profile,
                               const std::string& variant = "");

}  // namespace lt
