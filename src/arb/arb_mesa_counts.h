// What Mesa makes of an ARB program text: whether glProgramStringARB accepts it (and where it
// stops if not), and its GL_PROGRAM_NATIVE_* and GL_PROGRAM_* counts. The native figures are the
// program as written; the API ones include what Mesa appends (the 4 DP4 of
// ARB_position_invariant, the fog code of ARB_fog_*), as measured on Mesa 22's llvmpipe. Needs a
// current GL context (gl::Context).
#pragma once

#include <string>

#include "arb/arb_counter.h"

namespace lt::arbfp {

struct MesaFigures {
  // -1 where GL has no such query for the program kind (ALU, TEX and indirections of a vertex
  // program).
  int instructions = -1, alu = -1, tex = -1, indirections = -1, temporaries = -1, parameters = -1,
      attributes = -1, address_registers = -1;
};

struct MesaCounts {
  bool accepted = false;
  int error_offset = -1;  // GL_PROGRAM_ERROR_POSITION_ARB, a byte offset into the text
  std::string error;      // GL_PROGRAM_ERROR_STRING_ARB
  MesaFigures native, api;
  std::string renderer;  // GL_RENDERER, for the report
};

MesaCounts mesa_counts(budget::ProgramKind kind, const std::string& source);

}  // namespace lt::arbfp
