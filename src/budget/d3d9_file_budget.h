// `ltrender budget FILE.asm|FILE.vsh|FILE.psh` (or text whose first code line is a version
// token): a Direct3D 9 shader assembly program read (d3d9_asm_parser.h), counted as fxc counts
// it (d3d9_asm_counter.h) and checked against a profile (arb_profiles.h: ps_2_0, ps_2_a, ps_2_b,
// ps_3_0, vs_1_1, vs_2_0, vs_3_0, ...), with fxc's own count from the listing's comment
// (d3d9_fxc_comment.h) as each figure's cross-check where the file has one.
#pragma once

#include <string>

#include "budget/report.h"

namespace lt::d3d9 {

// `profile` empty: the version's own (ps_2_0 for ps_2_0, ps_2_x's minimum for ps_2_x, ...); a
// profile of the other kind checks through its partner. Throws InputError(file, "line:column",
// ...) for a program that is not valid for its version.
budget::Report budget_d3d9_file(const std::string& file, const std::string& profile);

}  // namespace lt::d3d9
