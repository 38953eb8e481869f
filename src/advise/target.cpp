#include "advise/target.h"

#include "core/error.h"
#include "paths/arbfp/arb_profiles.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/gx/gx_budget.h"

namespace lt::advise {

namespace {

// Each budget's profiles, by the path that owns the budget.
std::vector<std::pair<std::string, std::string>> known_profiles() {
  std::vector<std::pair<std::string, std::string>> out;
  for (const budget::Profile& p : budget::all_profiles()) out.emplace_back(p.name, "arbfp");
  for (const CombinerBudgetProfile& p : combiner_budget_profiles())
    out.emplace_back(p.name, "combiners");
  for (const gx::GxProfile& p : gx::gx_profiles()) out.emplace_back(p.name, "gx");
  return out;
}

}  // namespace

Target find_target(const std::string& profile) {
  std::string valid;
  for (const auto& [name, path] : known_profiles()) {
    if (name == profile) {
      Target t;
      t.profile = profile;
      t.path = &find_path(path);
      if (t.path->takes_profile) t.options.profile = profile;
      return t;
    }
    valid += (valid.empty() ? "" : ", ") + name + " (" + path + ")";
  }
  throw InputError("--target", profile, "unknown profile (valid: " + valid + ")");
}

}  // namespace lt::advise
