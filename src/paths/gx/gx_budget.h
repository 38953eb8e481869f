// The gx path's budget (`ltrender budget SCENE --path gx`): the pass programs it generates for a
// scene, counted and checked as any GX program is (budget/gx_program_budget.h).
#pragma once

#include <string>

#include "budget/gx_program_budget.h"
#include "scene/scene.h"

namespace lt::gx {

// `variant` "" is t=vertex, `profile` "" wii-tev.
budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile);

}  // namespace lt::gx
