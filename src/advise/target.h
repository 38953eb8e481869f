// The target `ltrender advise --target PROFILE` names: a hardware profile of one path's budget
// (ps_2_0 and the other ARB profiles: arbfp; the GL 1.3 combiner profiles: combiners; wii-tev:
// gx), so the profile decides which path serves it and which budget a candidate must fit.
#pragma once

#include <string>

#include "paths/path.h"

namespace lt::advise {

struct Target {
  std::string profile;
  const PathInfo* path = nullptr;
  // What the path is built with: the profile when the path takes one (arbfp splits a program
  // over it into passes), else nothing.
  PathOptions options;
};

// Throws InputError("--target", profile, ...) listing every profile the budgets know.
Target find_target(const std::string& profile);

}  // namespace lt::advise
