// An ARB_vertex_program / ARB_fragment_program as data: registers as handles into the program's
// declarations, instructions as opcode + operands, and the comments and blank lines where they
// print. The generator builds one (arb_generator.cpp), the budget counts it (arb_ir_counter.h)
// and print() writes the assembly text GL loads. Hand-written programs stay text and go through
// the text counter (arb_counter.h).
#pragma once

#include <string>
#include <vector>

#include "paths/arbfp/arb_counter.h"

namespace lt::arbfp::ir {

using budget::ProgramKind;

enum class File {
  Temp,    // a TEMP of the program
  Param,   // a PARAM of the program
  Attrib,  // an input binding: vertex.normal, fragment.texcoord[1]
  Output,  // an output binding: result.color, result.texcoord[3]
};

// One operand. Temporaries and parameters are handles (index) into the program that declared
// them; attributes and outputs are named by their binding. A source may be swizzled and negated,
// a destination masked; the helpers return modified copies, so a declared register can be
// passed around and read or written part by part.
struct Reg {
  File file = File::Temp;
  int index = -1;          // Temp, Param: the declaration; -1 is no register (an error to use)
  std::string binding;     // Attrib, Output
  std::string swizzle;     // as a source: "" (.xyzw), "x", "xyz", ...
  std::string write_mask;  // as a destination: "" (all), "xyz", ...
  bool negate = false;

  Reg swz(const std::string& components) const;
  Reg masked(const std::string& components) const;
  Reg operator-() const;
  // The same register and components as a destination: r.x read, r.x written.
  Reg as_destination() const;
  bool valid() const { return file == File::Attrib || file == File::Output || index >= 0; }
  bool same_register(const Reg& o) const;
};

Reg attrib(const std::string& binding);
Reg output(const std::string& binding);

// The opcodes of ARBvp1.0 and ARBfp1.0 except ARL and SWZ (address registers and extended
// swizzles: nothing generates them).
enum class Op {
  ABS,
  ADD,
  CMP,
  COS,
  DP3,
  DP4,
  DPH,
  DST,
  EX2,
  EXP,
  FLR,
  FRC,
  KIL,
  LG2,
  LIT,
  LOG,
  LRP,
  MAD,
  MAX,
  MIN,
  MOV,
  MUL,
  POW,
  RCP,
  RSQ,
  SCS,
  SGE,
  SIN,
  SLT,
  SUB,
  TEX,
  TXB,
  TXP,
  XPD,
};

struct OpInfo {
  const char* name;
  int sources;
  bool texture;  // a texture instruction of ARB_fragment_program (counted as TEX, not ALU)
  bool in_vertex, in_fragment;
};
const OpInfo& info(Op op);

struct Instr {
  Op op = Op::MOV;
  bool saturate = false;  // _SAT (fragment programs only)
  Reg dst;                // none for KIL
  std::vector<Reg> srcs;
  int texture_unit = 0;        // texture instructions: texture[unit], target
  std::string texture_target;  // "1D", "2D", ...
  std::string comment;         // printed after the instruction: "MUL a, b, c;  # comment"
};

struct Param {
  std::string name;
  std::string value;    // as printed: "{1, 2, 3, 0}"
  std::string comment;  // printed after the declaration
};

class Block;

// A program: its declarations, and its text as blocks of lines (comments, declarations,
// instructions) that print in the order the blocks were opened. Blocks let a generator write a
// declaration where it prints (before the TEMP statement) while it is emitting code further down.
class Program {
 public:
  explicit Program(ProgramKind kind = ProgramKind::Fragment) : kind_(kind) {}

  ProgramKind kind() const { return kind_; }
  const std::vector<std::string>& options() const { return options_; }
  const std::vector<std::string>& temps() const { return temps_; }
  const std::vector<Param>& params() const { return params_; }
  // Every instruction, in print order.
  std::vector<Instr> instructions() const;
  // Declared names, for printing: temps()[r.index] or params()[r.index].name.
  const std::string& name(const Reg& r) const;

  // Declares a temporary; the TEMP statement (Block::temps) lists them in this order.
  Reg temp(const std::string& name);
  // A new block after every block opened so far.
  Block block();

 private:
  friend class Block;
  friend std::string print(const Program& p);
  struct Line {
    enum class Kind { Text, Option, Param, Temps, Instr } kind;
    std::string text;  // Text: comment or blank lines, as printed
    size_t index = 0;  // Option, Param, Instr: into options_, params_, instrs_
  };
  void check_new_name(const std::string& name) const;
  void check(const Instr& in) const;

  ProgramKind kind_;
  std::vector<std::string> options_, temps_;
  std::vector<Param> params_;
  std::vector<Instr> instrs_;
  std::vector<std::vector<Line>> blocks_;
};

// Appends to one block of a program. Holds a pointer to the program: use it while the program
// is neither moved nor destroyed (during generation).
class Block {
 public:
  // Comment lines ("# ...\n") and blank lines ("\n"), printed as they are.
  void text(const std::string& lines);
  void option(const std::string& name);
  Reg param(const std::string& name, const std::string& value, const std::string& comment = "");
  // The program's TEMP statement prints here (nothing when there are no temporaries).
  void temps();
  void emit(Instr in);
  void op(Op op, const Reg& dst, std::vector<Reg> srcs, const std::string& comment = "");
  void op_sat(Op op, const Reg& dst, std::vector<Reg> srcs);
  void tex(const Reg& dst, const Reg& coord, int unit, const std::string& target);

  Program& program() const { return *program_; }
  ProgramKind kind() const { return program_->kind(); }

 private:
  friend class Program;
  Block(Program& p, size_t index) : program_(&p), index_(index) {}
  void add(Program::Line line);
  Program* program_;
  size_t index_;
};

// The assembly text: the header (!!ARBvp1.0 / !!ARBfp1.0), every block, END.
std::string print(const Program& p);

// Literals for PARAM values. A float literal as the program reads it: the double rounded to
// float, printed with %.9g, which round-trips a float exactly.
std::string num(double v);
// "{x, y, z, w}" with num().
std::string vec4(double x, double y, double z, double w);

}  // namespace lt::arbfp::ir
