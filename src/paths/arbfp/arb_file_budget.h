// `ltrender budget FILE.fp|FILE.vp|FILE.arb`: a hand-written ARB program counted by the text
// counter (arb_counter.h) against a profile (arb_profiles.h), and handed to Mesa
// (arb_mesa_counts.h) whose GL_PROGRAM_NATIVE_* figures each count is compared with. Every figure
// says which rule it follows and, where Mesa's differs by rule (END counted, parameters merged,
// indirections not computed), why; a difference no rule explains is reported as one.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "paths/arbfp/arb_mesa_counts.h"
#include "paths/arbfp/arb_profiles.h"

namespace lt::arbfp {

// One row of the report.
struct BudgetFigure {
  std::string key;     // JSON name: "alu", "tex", "instruction_slots", ...
  std::string label;   // "ALU instructions"
  int count = 0;       // ours, the figure checked against the profile
  int limit = -1;      // the profile's, -1 for none
  int mesa = -1;       // Mesa's native figure, -1 where GL has none for this kind
  bool agrees = true;  // Mesa's figure is what the rule predicts from ours
  std::string rule;    // how ours is counted and how Mesa's relates to it
};

struct FileBudget {
  std::string file, header;
  budget::ProgramKind kind = budget::ProgramKind::Fragment;
  std::vector<std::string> options;
  const budget::Profile* profile = nullptr;
  budget::ProgramCounts counts;
  std::vector<budget::Overrun> over;
  MesaCounts mesa;
  std::vector<BudgetFigure> figures;
  std::vector<std::string> notes;  // Mesa's API-level additions, and what the profile makes of them

  bool fits() const { return over.empty(); }
  // "prog.fp: 70 ALU instructions > 64 (ps_2_0)"; empty when it fits.
  std::string first_overrun() const;
};

// Reads, parses, counts and checks `file` against `profile` (empty: ps_2_0 for a fragment
// program, vs_2_0 for a vertex program; a profile of the other kind checks through its
// partner). Creates its own GL context for Mesa. Throws InputError(file, "line:column",
// "expected ...") for a program that is not valid, ours or Mesa's verdict.
FileBudget budget_arb_file(const std::string& file, const std::string& profile);

std::string to_text(const FileBudget& b);
// The stable schema of docs/budget.md "budget FILE.fp|FILE.vp".
nlohmann::json to_json(const FileBudget& b);

}  // namespace lt::arbfp
