// What a GX program uses of the Wii's GX (gx.md §2), counted on the GX state the program leaves
// (never on its text), against the hardware limits of gx-hardware.md §4: the counter, the
// profile, the report of a list of pass programs, and `ltrender budget FILE.c` (a program file).
// The gx path's `budget SCENE --path gx` counts its generated programs through the same report
// (paths/gx/gx_budget.h).
#pragma once

#include <string>
#include <vector>

#include "budget/report.h"
#include "gx/gx_state.h"
#include "gx/program/pass_programs.h"

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
// material is known (`material_names`, by index, else the program's own), else by its function;
// one row (scope material) per material with its passes (additive EFB blending: no hardware
// limit). `profile` "" is wii-tev.
budget::Report gx_programs_report(const std::vector<std::vector<PassProgram>>& by_material,
                                  const std::vector<std::string>& material_names,
                                  const std::string& profile);
budget::Report gx_budget_file(const std::string& program_file, const std::string& profile);

}  // namespace lt::gx
