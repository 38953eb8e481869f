// The arbfp path's budget (`ltrender budget SCENE --path arbfp`): every program it generates for
// a scene, counted on its instruction list (arb_ir_counter.h) and checked against a profile pair
// (arb_profiles.h), plus the translucency term's own cost per light: the program with the term
// minus the same program without it. It lives with the path (no other folder includes the ARB
// generator).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "paths/arbfp/arb_profiles.h"
#include "scene/scene.h"

namespace lt::budget {

struct CountedProgram {
  std::string name;  // e.g. "material marble: fragment program"
  ProgramCounts counts;
  std::string profile;  // the profile it was checked against
  std::vector<Overrun> over;
};

// The term's cost in one material's fragment program: entry k is what light k adds (the first
// includes the view vector, which only the term needs).
struct TermCost {
  std::string material;
  struct Cost {
    int alu = 0, tex = 0;
  };
  std::vector<Cost> per_light;
  Cost total;
};

// One pass of a material's pass plan for the profile (arb_passes.h).
struct PlannedPass {
  std::string material, lights;  // lights: "lights 0-4 + ambient"
  ProgramCounts vertex, fragment;
};

struct BudgetReport {
  std::string scene, path, variant;
  const Profile* fragment_profile = nullptr;
  const Profile* vertex_profile = nullptr;
  std::vector<CountedProgram> programs;
  std::vector<TermCost> term_costs;
  // The passes `render --profile` draws (one per material when its programs fit); empty with
  // pass_plan_error set when some light does not fit even alone.
  std::vector<PlannedPass> pass_plan;
  std::string pass_plan_error;

  bool fits() const;
  // "material marble: fragment program: 70 ALU instructions > 64 (ps_2_0)"; empty when it fits.
  std::string first_overrun() const;
};

// Throws InputError for an unknown path/profile/variant, or a path with no budget yet.
// `profile` may name either kind; its partner checks the other kind of program.
BudgetReport run_budget(const Scene& scene, const std::string& path, const std::string& variant,
                        const std::string& profile);

std::string format_table(const BudgetReport& report);
nlohmann::json to_json(const BudgetReport& report);

}  // namespace lt::budget
