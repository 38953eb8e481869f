// The tables of the ARB program grammar the parser (arb_text_parser.cpp) reads: the opcodes of
// ARB_vertex_program 2.14.5 and ARB_fragment_program 3.11.5 with their operand forms, the
// reserved words, the options of each program kind, and the generic vertex attributes that alias
// a named one.
#pragma once

#include <string>

#include "arb/arb_ir.h"

namespace lt::arbfp::text {

// How an opcode reads its operands (the instruction tables of ARB_vertex_program 2.14.5 and
// ARB_fragment_program 3.11.5).
enum class Form {
  Vector,   // vector sources: ABS ADD CMP DP3 ... XPD
  Scalar,   // scalar sources (a one-component swizzle): COS EX2 LG2 POW RCP RSQ SCS SIN, EXP LOG
  Swizzle,  // SWZ: a source register and an extended swizzle
  Texture,  // TEX TXP TXB: a vector source, texture[n], a target
  Kill,     // KIL: one vector source, no destination
  Address,  // ARL: the address register, a scalar source
};

// The name, the sources and the program kinds are the instruction's (ir::info).
struct OpcodeInfo {
  ir::Op op;
  Form form;
};

// The opcode of that name (without _SAT), or nullptr.
const OpcodeInfo* find_opcode(const std::string& name);
// Names the grammar reserves: a program cannot declare them.
bool reserved(const std::string& name);
// Whether `name` is an OPTION of fragment (or vertex) programs.
bool known_option(const std::string& name, bool vertex);
// The named attribute a generic vertex.attrib[n] aliases ("" when none), and the reverse.
std::string named_alias_of_generic(const std::string& binding);
std::string generic_of_named(const std::string& binding);

}  // namespace lt::arbfp::text
