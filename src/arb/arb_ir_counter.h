// The one counter of an ARB program (arb_counter.h's figures), read off the instruction list
// and the declarations of an ir::Program: one the generator built or one the text parser read
// (arb_text_parser.h), so generated and hand-written programs count alike.
#pragma once

#include "arb/arb_counter.h"
#include "arb/arb_ir.h"

namespace lt::arbfp::ir {

budget::ProgramCounts count(const Program& p);

}  // namespace lt::arbfp::ir
