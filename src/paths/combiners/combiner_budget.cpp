#include "paths/combiners/combiner_budget.h"

#include <algorithm>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.h"
#include "core/fs.h"
#include "paths/combiners/combiner_program.h"
#include "paths/combiners/combiners_path.h"

namespace lt {

const std::vector<CombinerBudgetProfile>& combiner_budget_profiles() {
  static const std::vector<CombinerBudgetProfile> profiles = {
      // GeForce2 (NV15): 2 texture units, register combiners exposed as 2 env stages.
      {"gl13-2units", "GeForce2-class: 2 texture units = 2 combiner stages", 2, 2, 2, 8},
      // Radeon 7500 (R100): 3 texture units.
      {"gl13-3units", "Radeon 7500-class: 3 texture units = 3 combiner stages", 3, 3, 3, 8},
      // What Mesa (llvmpipe) exposes to fixed-function GL: GL_MAX_TEXTURE_UNITS = 8.
      {"gl-8units", "Mesa llvmpipe fixed function: 8 texture units", 8, 8, 8, 8},
  };
  return profiles;
}

namespace {

const CombinerBudgetProfile& find_profile(const std::string& profile) {
  const auto& profiles = combiner_budget_profiles();
  const auto it = std::find_if(profiles.begin(), profiles.end(),
                               [&](const CombinerBudgetProfile& p) { return p.name == profile; });
  if (it == profiles.end()) {
    std::string names;
    for (const auto& p : profiles) names += (names.empty() ? "" : ", ") + p.name;
    // The Wii is not GL 1.3 state: its profile belongs to the gx path, which counts a real TEV.
    const std::string hint = profile == "wii-tev" ? "; wii-tev is the gx path's (--path gx)" : "";
    throw InputError("--profile", profile,
                     "unknown combiner profile (valid: " + names + ")" + hint);
  }
  return *it;
}

// GL 1.3 runs stage N on unit N and skips a unit with texturing off, so every stage costs a
// unit; the colour sum after the combiners is free.
void add_program(CombinerBudgetMaterial& m, const combiners::CombinerProgram& program) {
  const int program_stages = static_cast<int>(program.stages.size());
  m.stages = std::max(m.stages, program_stages);
  m.texture_units = std::max(m.texture_units, program_stages);
  m.constant_colors = std::max(m.constant_colors, program.constant_colors());
}

void add_material(CombinerBudgetReport& r, const CombinerBudgetMaterial& m) {
  r.stages = std::max(r.stages, m.stages);
  r.texture_units = std::max(r.texture_units, m.texture_units);
  r.constant_colors = std::max(r.constant_colors, m.constant_colors);
  r.passes = std::max(r.passes, m.passes);
  r.materials.push_back(m);
}

void check_limits(CombinerBudgetReport& r) {
  auto check = [&](const char* what, int used, int limit) {
    if (used > limit) {
      r.over.push_back(std::string(what) + ": " + std::to_string(used) + " > " +
                       std::to_string(limit));
    }
  };
  check("stages", r.stages, r.profile.stages);
  check("texture units", r.texture_units, r.profile.texture_units);
  check("constant colours", r.constant_colors, r.profile.constant_colors);
  // Per-vertex lighting runs on the CPU here, but a port would hand it to the hardware lights.
  check("lights", r.lights, r.profile.lights);
}

}  // namespace

CombinerBudgetReport combiner_budget(const Scene& scene, const std::string& profile,
                                     const std::string& variant) {
  CombinerBudgetReport r;
  r.profile = find_profile(profile);
  r.variant = variant.empty() ? "t=vertex" : variant;
  r.lights = static_cast<int>(scene.lights.size());
  for (const CombinerMaterialPlan& plan : plan_combiners(scene, r.variant)) {
    if (!plan.used) continue;
    CombinerBudgetMaterial m;
    m.material = scene.materials[plan.material].name;
    // A pass is one program: the limits apply to the largest program the material uses.
    for (const auto& [kind, program] : plan.programs) {
      if (!m.program.empty()) m.program += '+';
      m.program += program_file(kind);
      add_program(m, program);
    }
    m.passes = plan.passes();
    add_material(r, m);
  }
  check_limits(r);
  return r;
}

CombinerBudgetReport combiner_budget_file(const std::string& file, const std::string& profile) {
  CombinerBudgetReport r;
  r.profile = find_profile(profile);
  r.variant = "(program file)";
  const combiners::CombinerProgram program =
      combiners::parse_combiner_program(read_input_file(file, InputKind::Program), file);
  CombinerBudgetMaterial m;
  m.material = program.name;
  m.program = file;
  add_program(m, program);
  m.passes = 1;  // one file is one pass's state
  add_material(r, m);
  check_limits(r);
  return r;
}

std::string to_text(const CombinerBudgetReport& r) {
  std::ostringstream o;
  o << "profile " << r.profile.name << " (" << r.profile.summary << "), path combiners, variant "
    << r.variant << "\n";
  for (const CombinerBudgetMaterial& m : r.materials) {
    o << "  material " << m.material << ": combiners/" << m.program << ": " << m.stages
      << " stages, " << m.texture_units << " texture units, " << m.constant_colors
      << " constant colours, " << m.passes << " passes\n";
  }
  o << "  stages " << r.stages << "/" << r.profile.stages << ", texture units " << r.texture_units
    << "/" << r.profile.texture_units << ", constant colours " << r.constant_colors << "/"
    << r.profile.constant_colors << ", lights " << r.lights << "/" << r.profile.lights
    << ", passes " << r.passes << " (multipass: no limit)\n";
  if (r.fits()) {
    o << "  fits\n";
  } else {
    for (const std::string& s : r.over) o << "  OVER " << s << "\n";
  }
  return o.str();
}

std::string to_json(const CombinerBudgetReport& r) {
  nlohmann::json j;
  j["profile"] = r.profile.name;
  j["path"] = "combiners";
  j["variant"] = r.variant;
  j["fits"] = r.fits();
  j["over"] = r.over;
  j["used"] = {{"stages", r.stages},
               {"texture_units", r.texture_units},
               {"constant_colors", r.constant_colors},
               {"passes", r.passes},
               {"lights", r.lights}};
  j["limits"] = {{"stages", r.profile.stages},
                 {"texture_units", r.profile.texture_units},
                 {"constant_colors", r.profile.constant_colors},
                 {"lights", r.profile.lights}};
  nlohmann::json mats = nlohmann::json::array();
  for (const CombinerBudgetMaterial& m : r.materials) {
    mats.push_back({{"material", m.material},
                    {"program", m.program},
                    {"stages", m.stages},
                    {"texture_units", m.texture_units},
                    {"constant_colors", m.constant_colors},
                    {"passes", m.passes}});
  }
  j["materials"] = mats;
  return j.dump();
}

}  // namespace lt
