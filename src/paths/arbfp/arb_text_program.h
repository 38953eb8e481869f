// A hand-written ARB_vertex_program / ARB_fragment_program as the text parser
// (arb_text_parser.h) reads it: options, declarations, and instructions whose operands are
// resolved to what they name (a temporary, a parameter slot, an input or output binding). The
// counter (arb_counter.h) reads this; the generator's programs are ir::Program (arb_ir.h), which
// print to text this parser reads back.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "paths/arbfp/arb_counter.h"
#include "paths/arbfp/arb_text_lexer.h"

namespace lt::arbfp::text {

using budget::ProgramKind;

// Implementation limits the parser checks, as Mesa 22's llvmpipe reports them
// (glGetIntegerv / glGetProgramivARB): a driver's compiler refuses an index past them.
struct Limits {
  int texture_coords = 8;        // GL_MAX_TEXTURE_COORDS
  int texture_image_units = 32;  // GL_MAX_TEXTURE_IMAGE_UNITS
  int vertex_attribs = 16;       // GL_MAX_VERTEX_ATTRIBS
  int lights = 8, clip_planes = 8, program_matrices = 8, draw_buffers = 8;
  int env_params = 256, local_params = 2048;  // GL_MAX_PROGRAM_ENV/LOCAL_PARAMETERS
  int address_offset = 64;  // |n| of a[A0.x + n] (Mesa accepts 64; the spec's minimum is 63)
};

// One slot of the parameter file (a vec4): a constant, or a state / program binding.
struct ParamSlot {
  bool constant = false;
  std::array<float, 4> values = {0, 0, 0, 0};
  // Components that are the constant's own: 1 for a scalar used in an instruction ("0.5"), 4
  // for every vector and every declared PARAM (Mesa's paramConstScalarUse / paramConstVector).
  int size = 4;
  std::string binding;  // canonical, e.g. "state.matrix.mvp.row[1]", "program.local[3]"
};

struct ParamDecl {
  std::string name;
  std::vector<ParamSlot> slots;
  bool array = false;
  size_t after_instructions = 0;  // instructions before the declaration (Mesa's list order)
};

enum class RegFile { Temp, Param, InlineParam, Attrib, Output, Address };

struct Operand {
  RegFile file = RegFile::Temp;
  int index = -1;       // Temp: into temps; Param: into params; Address: into addresses
  int element = 0;      // Param: the array element; -1 for relative addressing (a[A0.x + n])
  ParamSlot slot;       // InlineParam: the constant or binding used in the instruction
  std::string binding;  // Attrib, Output: canonical ("fragment.texcoord[0]", "result.color")
  std::string swizzle;  // source: "" or the components as written; destination: the mask
  bool negate = false;
};

struct Instruction {
  std::string opcode;  // without _SAT
  bool saturate = false;
  bool texture = false;  // TEX, TXP, TXB, KIL: texture instructions (ARB_fragment_program 3.11.5)
  Position at;
  bool has_dst = true;  // false for KIL
  Operand dst;
  std::vector<Operand> srcs;
  int unit = -1;  // texture instructions but KIL
  std::string target;
};

struct Program {
  ProgramKind kind = ProgramKind::Fragment;
  std::string header;  // "!!ARBfp1.0"
  std::vector<std::string> options;
  std::vector<std::string> temps, addresses;
  std::vector<ParamDecl> params;
  std::vector<Instruction> code;

  bool has_option(const std::string& name) const;
};

}  // namespace lt::arbfp::text
