#include "advise/target.h"

#include "core/error.h"
#include "paths/path.h"

namespace lt::advise {

// The profiles are the registry's: each path lists those of its budget (PathInfo::
// budget_profiles), so a profile a path adds is a target here with nothing else to change.
Target find_target(const std::string& profile) {
  std::string valid;
  for (const PathInfo& path : all_paths()) {
    for (const std::string& name : path.budget_profiles) {
      if (name == profile) {
        Target t;
        t.profile = profile;
        t.path = &path;
        if (path.takes_profile) t.options.profile = profile;
        return t;
      }
      valid += (valid.empty() ? "" : ", ") + name + " (" + path.name + ")";
    }
  }
  throw InputError("--target", profile, "unknown profile (valid: " + valid + ")");
}

}  // namespace lt::advise
