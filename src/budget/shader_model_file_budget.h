// `ltrender budget FILE` for the SM2-class shader languages, the arbfp path's kind of program
// file: hand-written ARB_vertex_program / ARB_fragment_program text, checked by our counter and
// by Mesa (arb_file_budget.h), or Direct3D 9 assembly, the same shader model's other language,
// counted as fxc counts it against the same profiles (d3d9_file_budget.h).
#pragma once

#include <string>

#include "budget/report.h"

namespace lt::budget {

// Whether `text` (a file's whose extension no path claims) is a program in one of the two
// languages: an ARB header ("!!ARBfp1.0" / "!!ARBvp1.0" after white space), or a D3D9 version
// token on its first code line.
bool is_shader_model_program_text(const std::string& text);

// `file` counted against `profile` ("" the language's default): an ARB header wins; then a D3D9
// extension (.asm, .vsh, .psh) or a version token on the first code line makes it D3D9
// assembly; anything else is read as ARB text.
Report budget_shader_model_file(const std::string& file, const std::string& profile);

}  // namespace lt::budget
