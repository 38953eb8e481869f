// The pieces of ARB program text the parser (arb_text_parser.cpp) reads inside an operand or a
// PARAM: numbers, vector constants, write masks, swizzles and SWZ's extended swizzle. Each reads
// from the cursor and throws SyntaxError where the grammar of ARB_vertex_program 2.14.2 /
// ARB_fragment_program 3.11.2 is not met; `vertex` is the program kind (rgba is fragment
// programs' only).
#pragma once

#include <string>

#include "arb/arb_ir.h"
#include "arb/arb_text_cursor.h"

namespace lt::arbfp::text {

// An optionally signed integer or float.
float signed_number(Cursor& c);
// '{' a [, b [, c [, d]]] '}': missing components are (0, 0, 1) as in ARB_vertex_program
// 2.14.3.4 ({x} is (x, 0, 0, 1)).
ir::ParamSlot vector_constant(Cursor& c);
// Whether the token `ahead` of the cursor is a number.
bool starts_number(const Cursor& c, size_t ahead = 0);
// ".mask" of a destination: components in xyzw order, each once (rgba too in fragment programs);
// "" when there is none.
std::string write_mask(Cursor& c, bool vertex);
// ".x" or ".xyzw" of a source (one or four components, ARB_vertex_program 2.14.2.2); `scalar`:
// exactly one.
std::string swizzle(Cursor& c, bool vertex, bool scalar);
// SWZ's four components: 0, 1, or a component, each with an optional sign ("0,1,-x,y" as
// "01-xy").
std::string extended_swizzle(Cursor& c, bool vertex);

}  // namespace lt::arbfp::text
