// Which GX state each pass of each material draws with. A program file either is one plain list
// of calls (gx.md §1's example: one pass, used by every material) or holds pass functions named
// `ltrender_<material>_pass<N>` (what `ltrender export gx` writes); each pass function runs on
// a fresh GX_Init state after the file's top-level statements, so every pass is self-contained,
// as code that may be called in any order must be.
#pragma once

#include <string>
#include <vector>

#include "paths/gx/gx_state.h"
#include "paths/gx/program/program_file.h"
#include "scene/scene.h"

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

// The passes of every scene material (index = material): a plain file's one program for all,
// or the file's pass functions of that material, pass 0..N-1 with none missing. Throws
// InputError naming a material some object uses that the file has no pass for.
std::vector<std::vector<PassProgram>> scene_programs(const ProgramFile& file, const Scene& scene);

// The C identifier of every scene material (index = material), used both to write the pass
// functions and to read them back: the name with every character C does not allow in an
// identifier replaced by '_', and where that is already an earlier material's (e.g.
// "Material.20" and "Material_20"), suffixed _2, _3, ... until it is unique. Materials no object
// uses take part too, so a name does not depend on which objects a scene draws.
std::vector<std::string> material_c_names(const Scene& scene);
// `ltrender_<c_name>_pass<N>`.
std::string pass_function_name(const std::string& c_name, int pass);

}  // namespace lt::gx
