// What an ARB_vertex_program / ARB_fragment_program uses, as the specs define the limits: ALU and
// TEX instructions, temporaries, parameters, attributes and (fragment programs) texture
// indirections by the algorithm of ARB_fragment_program issue 24. The one counter
// (arb_ir_counter.h) fills it from the instruction list, generated or parsed from text, so it
// needs no GL context and checks any program.
#pragma once

#include <string>

namespace lt::budget {

enum class ProgramKind { Vertex, Fragment };
const char* to_string(ProgramKind k);

struct ProgramCounts {
  ProgramKind kind = ProgramKind::Fragment;
  int alu = 0;  // every instruction of a vertex program; non-texture ones of a fragment program
  int tex = 0;  // TEX, TXP, TXB, KIL (ARB_fragment_program counts KIL as a texture instruction)
  int temporaries = 0;   // TEMP declarations (the API-level count, not what a driver allocates)
  int parameters = 0;    // PARAM slots (arrays count their size) + distinct inline constants and
                         // program.env/local/state bindings used directly in instructions
  int attributes = 0;    // distinct fragment.* / vertex.* inputs read
  int indirections = 1;  // texture indirections (fragment; 1 for a vertex program)
  int address_registers = 0;        // ADDRESS declarations (vertex programs)
  bool position_invariant = false;  // OPTION ARB_position_invariant (the driver adds 4 DP4)
  // The slots Mesa's parameter layout keeps (prog_parameter_layout.c): only referenced ones, a
  // relatively addressed array whole, equal constants merged, scalar literals packed four to a
  // slot; what GL_PROGRAM_NATIVE_PARAMETERS_ARB reports. -1 where not computed (a generated
  // program: its PARAM values are text).
  int referenced_parameters = -1;

  int instructions() const { return alu + tex; }
};

// The counts of program text: parsed (arb_text_parser.h), then counted (arb_ir_counter.h).
// Throws text::SyntaxError (a std::invalid_argument) at the first line and column that is not a
// valid program.
ProgramCounts count_program(const std::string& source);

}  // namespace lt::budget
