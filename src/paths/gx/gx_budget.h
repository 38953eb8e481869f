// The gx path's budget (gx.md §2): what each pass program uses of the Wii's GX, counted on the
// GX state the program leaves (never on its text), against the hardware limits of
// gx-hardware.md §4. `ltrender budget SCENE --path gx` counts the generated programs,
// `ltrender budget FILE.c` a program file.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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
// Throws InputError("--profile", ...) naming the valid profiles.
const GxProfile& find_gx_profile(const std::string& name);

struct GxBudgetProgram {
  std::string name;  // the pass function, or "(whole file)"
  std::string material;
  int pass = 0;
  GxCounts counts;
  std::vector<std::string> over;  // "TEV stages: 17 > 16"
};

struct GxBudgetReport {
  std::string source;   // the scene or the program file
  std::string variant;  // empty for a file
  GxProfile profile;
  std::vector<GxBudgetProgram> programs;
  int passes = 0;  // per frame: the most any material needs
  bool fits() const;
  std::string first_overrun() const;  // "material marble pass 0 (ltrender_marble_pass0): ..."
};

GxBudgetReport gx_budget_scene(const Scene& scene, const std::string& variant,
                               const std::string& profile);
GxBudgetReport gx_budget_file(const std::string& program_file, const std::string& profile);

std::string to_text(const GxBudgetReport& report);
// The schema: {source, variant, profile, fits, over: [..], passes, limits: {counts},
// programs: [{name, material, pass, counts: {...}, over: [..]}]}; counts keys are the GxCounts
// field names.
nlohmann::json to_json(const GxBudgetReport& report);

}  // namespace lt::gx
