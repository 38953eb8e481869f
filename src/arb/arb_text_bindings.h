// The bindings of ARB program text: inputs (fragment.*, vertex.*), outputs (result.*) and
// parameters (state.*, program.env/local), parsed from the cursor at the binding's first name
// into a canonical spelling (the default of each optional part filled in: fragment.color is
// fragment.color.primary), so equal bindings count once. Grammar: ARB_vertex_program 2.14.3,
// ARB_fragment_program 3.11.3; what Mesa 22 lacks (ARB_vertex_blend, ARB_matrix_palette) is refused
// as Mesa refuses it.
#pragma once

#include <string>
#include <vector>

#include "arb/arb_ir.h"
#include "arb/arb_text_cursor.h"

namespace lt::arbfp::text {

using budget::ProgramKind;
using ir::ParamSlot;

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

// The cursor is at "fragment" or "vertex": the input binding.
std::string parse_attrib_binding(Cursor& c, ProgramKind kind, const Limits& limits);

// The cursor is at "result": the output binding. `draw_buffers`: OPTION ARB_draw_buffers was
// given (result.color[n]).
std::string parse_result_binding(Cursor& c, ProgramKind kind, const Limits& limits,
                                 bool draw_buffers);

// The cursor is at "state" or "program": the slots the binding covers. A whole matrix is four
// rows, "row[a..b]" b - a + 1, "program.env[a..b]" likewise; `ranges` false refuses more than
// one slot (a single PARAM, an operand of an instruction).
std::vector<ParamSlot> parse_param_binding(Cursor& c, ProgramKind kind, const Limits& limits,
                                           bool ranges);

// Whether a name starts a binding of that family.
inline bool starts_attrib_binding(const Token& t) {
  return t.is("fragment") || t.is("vertex");
}
inline bool starts_param_binding(const Token& t) {
  return t.is("state") || t.is("program");
}

}  // namespace lt::arbfp::text
