// Counts what an ARB_vertex_program / ARB_fragment_program uses, as the specs define the limits:
// ALU and TEX instructions, temporaries, parameters, attributes and (fragment programs) texture
// indirections by the algorithm of ARB_fragment_program issue 24. Works on the program text
// (parsed by arb_text_parser.h), so it needs no GL context and checks any program, generated or
// hand-written.
#pragma once

#include <string>
#include <vector>

namespace lt::arbfp::text {
struct Program;
}

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
  // slot; what GL_PROGRAM_NATIVE_PARAMETERS_ARB reports. -1 where not computed (the IR counter).
  int referenced_parameters = -1;

  int instructions() const { return alu + tex; }
};

// What the texture-indirection count reads of one instruction: the temporaries by any numbering
// (-1 for none or not a temporary).
struct TemporaryUse {
  bool texture = false;   // TEX, TXP, TXB, KIL
  int dst = -1;           // the destination temporary (none for KIL)
  int coord = -1;         // texture instructions: the coordinate's temporary
  std::vector<int> srcs;  // ALU instructions: the sources' temporaries
};
// Texture indirections by the algorithm of ARB_fragment_program issue 24: a texture instruction
// starts a new indirection when its coordinate is a temporary written since the last one began,
// or when it overwrites a temporary an ALU instruction used since then. Both counters (text and
// IR) count through this.
int texture_indirections(const std::vector<TemporaryUse>& code);

// Throws text::SyntaxError (a std::invalid_argument) at the first line and column that is not a
// valid program.
ProgramCounts count_program(const std::string& source);
// The same counts of an already parsed program.
ProgramCounts count_parsed(const arbfp::text::Program& program);

}  // namespace lt::budget
