// Hardware profiles a program is checked against. Each limit says where it comes from; -1 means
// the profile sets no limit of that kind.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "arb/arb_counter.h"
#include "budget/report.h"

namespace lt::budget {

struct Profile {
  std::string name;
  ProgramKind kind;
  std::string partner;  // the profile for the other program kind (ps_2_0 <-> vs_2_0, ...)
  int alu = -1, tex = -1;
  int instructions = -1;  // ALU + TEX slots together
  int temporaries = -1, parameters = -1, attributes = -1;
  int indirections = -1;
  std::string source;  // where the numbers come from
  // D3D9 assembly: levels of texture reads, the first plus each dependent order ("texld - ps_2_0
  // and up": without NODEPENDENTREADLIMIT a read may be dependent to third order, 4 levels).
  int dependent_levels = -1;
};

const std::vector<Profile>& all_profiles();
// Throws InputError("--profile", name, ...) listing the valid names.
const Profile& find_profile(const std::string& name);
// The profile `name` (empty: `fallback`) as it applies to a program of `kind`: a profile of the
// other kind checks it through its partner (ps_2_0 given, a vertex program meets vs_2_0).
const Profile& profile_for(ProgramKind kind, const std::string& name, const std::string& fallback);
// A profile's limit as a report row holds it: none where the profile sets none (-1).
std::optional<int> limit_of(int max);

// One limit a program goes over, e.g. {"ALU instructions", 70, 64}.
struct Overrun {
  std::string limit;
  int count, max;
};
std::vector<Overrun> check(const ProgramCounts& counts, const Profile& profile);

// The rows of one program in the budget report, checked against `profile` by the same limits as
// check(): alu, tex and indirections (fragment programs), instruction_slots, temporaries,
// parameters, attributes, address_registers (no profile limits them).
std::vector<Resource> program_resources(const ProgramCounts& counts, const Profile& profile);

}  // namespace lt::budget
