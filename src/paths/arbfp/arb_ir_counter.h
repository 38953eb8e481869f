// Counts an ARB program built as IR (arb_ir.h) the way the text counter (arb_counter.h) counts
// its text: the same figures, read off the instruction list and the declarations instead of
// parsed back, so the budget needs no guess about which names are temporaries.
#pragma once

#include "paths/arbfp/arb_counter.h"
#include "paths/arbfp/arb_ir.h"

namespace lt::arbfp::ir {

budget::ProgramCounts count(const Program& p);

}  // namespace lt::arbfp::ir
