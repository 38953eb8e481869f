// Counts what an ARB_vertex_program / ARB_fragment_program uses, as the specs define the limits:
// ALU and TEX instructions, temporaries, parameters, attributes and (fragment programs) texture
// indirections by the algorithm of ARB_fragment_program issue 24. Works on the program text, so
// it needs no GL context and checks any program, generated or hand-written.
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
  bool position_invariant = false;  // OPTION ARB_position_invariant (the driver adds 4 DP4)

  int instructions() const { return alu + tex; }
};

// Throws std::invalid_argument naming the statement it cannot read.
ProgramCounts count_program(const std::string& source);

}  // namespace lt::budget
