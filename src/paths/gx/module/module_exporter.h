// `ltrender export gx --format module`: the generated programs as code a game runs every frame
// (issue 26). `--format c` prints one frame's numbers: the eye-space lights, the attenuation
// gains, the TEV scales and the ambient colour of that camera. A module prints the same plan with
// those fields read from a per-frame state (ltr_pass_state), and carries the C that computes
// the state from the game's camera, lights and meshes (runtime/ltrender_gx_runtime.c, the
// planner's choices in the planner's own order of operations), the per-vertex t and the draw.
#pragma once

#include <string>

#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

// The module's text. Throws InputError for whatever plan_scene refuses, and for a vertex storage
// or an indexed :draw= (its runtime sends each vertex F32, GX_DIRECT: ltrender_gx_draw.c).
// lobe=xf-spec's lobe is fitted again every frame (ltr_fit_lobe, model/rational_fit.cpp in C).
std::string export_module(const Scene& scene, const GxVariant& variant,
                          const std::string& scene_argument);

}  // namespace lt::gx
