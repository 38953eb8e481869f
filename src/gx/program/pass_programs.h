// Which GX state each pass of each material draws with. A program file either is one plain list
// of calls (gx.md §1's example: one pass, used by every material) or holds pass functions named
// `ltrender_<material>_pass<N>` (what `ltrender export gx` writes); each pass function runs on
// a fresh GX_Init state after the file's top-level statements, so every pass is self-contained,
// as code that may be called in any order must be.
#pragma once

#include <string>
#include <vector>

#include "gx/gx_state.h"
#include "gx/program/program_file.h"

namespace lt::gx {

struct PassProgram {
  std::string name;      // the function's name, or "(whole file)"
  std::string material;  // as written in the function name; empty for a plain file
  int pass = 0;
  GxState state;
};

// Every program of the file, in file order (for `budget FILE.c`). Throws InputError for a
// function whose name does not follow the rule, or a pass number given twice.
std::vector<PassProgram> file_programs(const ProgramFile& file);

// `ltrender_<c_name>_pass<N>` (paths/gx/scene_pass_programs.h material_c_names gives c_name).
std::string pass_function_name(const std::string& c_name, int pass);

}  // namespace lt::gx
