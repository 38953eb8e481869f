// Parses hand-written ARB_vertex_program / ARB_fragment_program text into the instruction list
// the generator builds (ir::Program, arb_ir.h), as Mesa's program_parse.y does, checking what a
// driver's compiler checks: the grammar of the two specs (every opcode, OPTIONs, PARAM arrays and
// bindings, ATTRIB, OUTPUT, ALIAS, ADDRESS, swizzles, masks, extended swizzles, relative
// addressing), names declared once before use, operands of the right file, array bounds, one target
// per texture unit, and the implementation limits of Mesa's llvmpipe (Limits). Where Mesa 22
// refuses a program the specs allow (a second precision hint, named and generic aliases of one
// vertex attribute) this parser refuses it too.
#pragma once

#include <string>

#include "arb/arb_ir.h"
#include "arb/arb_text_bindings.h"

namespace lt::arbfp::text {

// Throws SyntaxError at the first token that is not what the grammar or the checks expect.
ir::Program parse(const std::string& source, const Limits& limits = {});

}  // namespace lt::arbfp::text
