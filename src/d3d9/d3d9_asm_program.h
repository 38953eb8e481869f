// A Direct3D 9 shader assembly program as read from its text (d3d9_asm_parser.h): the version
// and the instruction list, each operand with its register, so the counter
// (d3d9_asm_counter.h) counts slots and registers on the list, never on the text.
#pragma once

#include <string>
#include <vector>

#include "arb/arb_text_lexer.h"  // Position, SyntaxError: one error style for both readers
#include "d3d9/d3d9_asm_instructions.h"

namespace lt::d3d9 {

using arbfp::text::Position;

struct Register {
  std::string type;       // lower case without the index: "r", "c", "oc", "opos", "vface"
  int index = 0;          // 0 for a register without one (oPos)
  bool relative = false;  // c[a0.x + 4], v[aL]: the index is a base
};

struct Operand {
  Register reg;
  bool negate = false;
};

struct Instruction {
  const InstructionInfo* info = nullptr;
  bool compared = false;  // a comparison suffix: if_gt, break_ne, setp_le
  Position at;
  std::vector<Operand> destinations;  // at most one
  std::vector<Operand> sources;       // registers only (def's numbers are not operands)
};

struct Program {
  Version version = Version::Ps20;
  Position version_at;
  std::vector<Instruction> instructions;  // in order; def and dcl included (0 slots)
};

}  // namespace lt::d3d9
