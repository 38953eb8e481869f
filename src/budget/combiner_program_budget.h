// Stage budgets of GL 1.3 combiner programs (combiner/combiner_program.h): what a program uses
// (combiner stages, texture units, constant colours) against what a class of hardware has, as a
// budget row; `ltrender budget FILE.comb` for one file. The combiners path's scene budget
// (paths/combiners/combiner_budget.h) fills its rows here. No GL context needed.
#pragma once

#include <string>
#include <vector>

#include "budget/report.h"
#include "combiner/combiner_program.h"

namespace lt {

struct CombinerBudgetProfile {
  std::string name;         // as given to --profile
  std::string summary;      // the hardware it stands for
  int stages = 0;           // combiner stages (texture environments / TEV stages)
  int texture_units = 0;    // texture units
  int constant_colors = 0;  // one TEXTURE_ENV_COLOR per unit
  int lights = 0;           // hardware lights per pass (GL_MAX_LIGHTS)
};

// gl13-2units, gl13-3units, gl-8units (the Wii's wii-tev is the GX's, gx_program_budget.h).
const std::vector<CombinerBudgetProfile>& combiner_budget_profiles();

// The profile named `profile` ("" is gl13-2units); throws InputError("--profile", profile, ...)
// naming the valid profiles for an unknown one.
const CombinerBudgetProfile& combiner_budget_profile(const std::string& profile);
// A row against `p` with every resource at 0, and a program added to it (a material's row holds
// the largest of its programs).
budget::Item combiner_budget_row(budget::Scope scope, const std::string& name,
                                 const CombinerBudgetProfile& p);
void add_combiner_program(budget::Item& item, const combiners::CombinerProgram& program);
// An empty report of `file` (`input` "scene" or "program") by the combiners path against `p`.
budget::Report combiner_budget_report(const std::string& file, const std::string& input,
                                      const CombinerBudgetProfile& p);

// `ltrender budget FILE.comb`: one hand-written combiner program (combiners/README.md) as one
// pass against the profile (one row, scope program). Throws InputError naming the file and
// line for a bad program.
budget::Report combiner_budget_file(const std::string& file, const std::string& profile);

}  // namespace lt
