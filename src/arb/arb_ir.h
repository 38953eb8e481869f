// An ARB_vertex_program / ARB_fragment_program as data: registers as handles into the program's
// declarations, instructions as opcode + operands, and the comments and blank lines where they
// print. The generator builds one (arb_generator.cpp) and print() writes the assembly text GL
// loads; the text parser (arb_text_parser.h) reads hand-written programs into one, as Mesa's
// program_parse.y reads text into the prog_instruction list it also generates. The one counter
// (arb_ir_counter.h) counts either.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "arb/arb_counter.h"

namespace lt::arbfp::ir {

using budget::ProgramKind;

enum class File {
  Temp,     // a TEMP of the program
  Param,    // a PARAM of the program
  Attrib,   // an input binding: vertex.normal, fragment.texcoord[1]
  Output,   // an output binding: result.color, result.texcoord[3]
  Address,  // an ADDRESS register (vertex programs: ARL's destination; read only inside a[...])
  Literal,  // a constant or a state / program binding written in the instruction (parsed text)
};

// One slot of the parameter file (a vec4): a constant, or a state / program binding. The
// parser's; a generated PARAM has none (its value is text, one slot).
struct ParamSlot {
  bool constant = false;
  std::array<float, 4> values = {0, 0, 0, 0};
  // Components that are the constant's own: 1 for a scalar used in an instruction ("0.5"), 4
  // for every vector and every declared PARAM (Mesa's paramConstScalarUse / paramConstVector).
  int size = 4;
  std::string binding;  // canonical, e.g. "state.matrix.mvp.row[1]", "program.local[3]"
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
  int element = 0;    // Param of an array (parsed text): the element; -1 for a[A0.x + n]
  ParamSlot literal;  // Literal

  Reg swz(const std::string& components) const;
  Reg masked(const std::string& components) const;
  Reg operator-() const;
  // The same register and components as a destination: r.x read, r.x written.
  Reg as_destination() const;
  bool valid() const {
    return file == File::Attrib || file == File::Output || file == File::Literal || index >= 0;
  }
  bool same_register(const Reg& o) const;
};

Reg attrib(const std::string& binding);
Reg output(const std::string& binding);

// The opcodes of ARBvp1.0 and ARBfp1.0 (the generator writes neither ARL nor SWZ; hand-written
// programs may).
enum class Op {
  ABS,
  ADD,
  ARL,
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
  SWZ,
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
  bool saturate = false;       // _SAT (fragment programs only)
  Reg dst;                     // none for KIL; ARL: the address register
  std::vector<Reg> srcs;       // SWZ: one, its swizzle the extended one ("0,1,-x,y" as "01-xy")
  int texture_unit = 0;        // texture instructions: texture[unit], target
  std::string texture_target;  // "1D", "2D", ...
  std::string comment;         // printed after the instruction: "MUL a, b, c;  # comment"
};

struct Param {
  std::string name;
  std::string value;    // as printed: "{1, 2, 3, 0}"
  std::string comment;  // printed after the declaration
  // A parsed PARAM: its slots (an array's every element) and the instructions before it (Mesa's
  // parameter list is built in statement order; a parsed program is one block, so this is its
  // place in print order too). A generated PARAM has no slots: one slot, its value as text.
  std::vector<ParamSlot> slots = {};
  bool array = false;
  size_t after_instructions = 0;
};

// The first line of a program's text: "!!ARBvp1.0" or "!!ARBfp1.0".
const char* header(ProgramKind kind);

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
  const std::vector<std::string>& addresses() const { return addresses_; }
  const std::vector<Param>& params() const { return params_; }
  // Every instruction, in print order.
  std::vector<Instr> instructions() const;
  bool has_option(const std::string& name) const;
  // Declared names, for printing: temps()[r.index], params()[r.index].name or addresses()[...].
  const std::string& name(const Reg& r) const;

  // Declares a temporary; the TEMP statement (Block::temps) lists them in this order.
  Reg temp(const std::string& name);
  // Declares an address register (vertex programs; ADDRESS statements are not printed).
  Reg address(const std::string& name);
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
  std::vector<std::string> options_, temps_, addresses_;
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
  // A parsed declaration (slots, array): printing it is not supported (its text is the source).
  Reg param(Param declaration);
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

// The assembly text: the header (!!ARBvp1.0 / !!ARBfp1.0), every block, END. Of a generated
// program: a parsed one's arrays, literals and address registers are not printed (its text is
// the source it was parsed from).
std::string print(const Program& p);

// Literals for PARAM values. A float literal as the program reads it: the double rounded to
// float, printed with %.9g, which round-trips a float exactly.
std::string num(double v);
// "{x, y, z, w}" with num().
std::string vec4(double x, double y, double z, double w);

}  // namespace lt::arbfp::ir
