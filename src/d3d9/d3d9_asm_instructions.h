// The instructions of Direct3D 9 shader assembly, vs_1_1 to ps_3_0: for each, which versions
// have it, how many instruction slots it takes in each (a macro such as m4x4 or sincos takes
// several, a declaration none) and whether it is arithmetic, texture, flow control or setup.
// The figures are the tables of the documentation's "Instructions - vs_1_1" ... "Instructions
// - ps_3_0" pages (learn.microsoft.com direct3dhlsl/dx9-graphics-reference-asm-*-instructions-*),
// except where fxc counts otherwise, each such place saying why (d3d9_asm_instructions.cpp).
#pragma once

#include <string>

#include "d3d9/d3d9_asm_version.h"

namespace lt::d3d9 {

enum class Kind { Setup, Arithmetic, Texture, Flow };

struct InstructionInfo {
  std::string name;
  Kind kind = Kind::Arithmetic;
  bool has_destination = true;
  bool compares = false;  // takes a comparison suffix: if_gt, break_ne, setp_le
};

// The instruction `name` (lower case, without modifiers) as `version` has it; nullptr when the
// name is no instruction of any version.
const InstructionInfo* find_instruction(const std::string& name);
// Its slots in `version`; -1 when the version lacks it. `compared`: written with a comparison
// suffix (break_gt is break_comp, if_gt is if_comp).
int slots(const InstructionInfo& info, Version version, bool compared = false);
// How many source operands it takes in `version` (sincos: 3 before shader model 3, 1 after).
int source_count(const InstructionInfo& info, Version version, bool compared = false);
// "ps_2_x, ps_3_0": the versions that have it, for the refusal.
std::string versions_with(const InstructionInfo& info);

}  // namespace lt::d3d9
