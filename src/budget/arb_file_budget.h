// `ltrender budget FILE.fp|FILE.vp|FILE.arb`: a hand-written ARB program counted by the text
// counter (arb_counter.h) against a profile (arb_profiles.h), and handed to Mesa
// (arb_mesa_counts.h) whose GL_PROGRAM_NATIVE_* figures each count is compared with. Every figure
// says which rule it follows and, where Mesa's differs by rule (END counted, parameters merged,
// indirections not computed), why; a difference no rule explains is reported as one.
#pragma once

#include <string>

#include "budget/arb_profiles.h"

namespace lt::arbfp {

// Reads, parses, counts and checks `file` against `profile` (empty: ps_2_0 for a fragment
// program, vs_2_0 for a vertex program; a profile of the other kind checks through its
// partner). Creates its own GL context for Mesa. One row (scope program): each figure with
// Mesa's as its cross-check and the rule that relates them; details: header, kind, options,
// Mesa's API-level counts. Throws InputError(file, "line:column", "expected ...") for a program
// that is not valid, ours or Mesa's verdict.
budget::Report budget_arb_file(const std::string& file, const std::string& profile);

}  // namespace lt::arbfp
