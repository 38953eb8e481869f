// The gx path's budget (gx.md §2): what each pass program uses of the Wii's GX, counted on the
// GX state the program leaves (never on its text), against the hardware limits of
// gx-hardware.md §4. `ltrender budget SCENE --path gx` counts the generated programs,
// `ltrender budget FILE.c` a program file.
#pragma once

#include <string>
#include <vector>

#include "paths/budget/report.h"
#include "paths/gx/gx_state.h"
#include "paths/gx/gx_variant.h"
#include "scene/scene.h"

namespace lt::gx {

struct GxCounts {
  int tev_stages = 0, texgens = 0, texture_maps = 0, channels = 0, lights_per_channel = 0,
      konst_colors = 0, tev_registers = 0, vertex_attributes = 0;
};
GxCounts count_program(const GxState& state);

struct GxProfile {
  std::string name, summary;
  GxCounts limits;
  std::string source;
};
// wii-tev (the Wii / GameCube GX).
const std::vector<GxProfile>& gx_profiles();

// One row (scope pass) per pass program, named "material M pass N (function)" where the
// material is known, else by its function; one row (scope material) per material with its passes
// (additive EFB blending: no hardware limit). `variant` "" is t=vertex, `profile` "" wii-tev.
budget::Report gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile);
budget::Report gx_budget_file(const std::string& program_file, const std::string& profile);

}  // namespace lt::gx
