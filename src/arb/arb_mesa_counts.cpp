#include "arb/arb_mesa_counts.h"

#include "arb/arb_program.h"

namespace lt::arbfp {

namespace {

// One figure, or -1 where the query is not one of this program kind's (GL_INVALID_ENUM).
int query(GLenum target, GLenum pname) {
  GLint v = -1;
  glGetProgramivARB(target, pname, &v);
  if (glGetError() != GL_NO_ERROR) return -1;
  return v;
}

MesaFigures query_figures(GLenum target, bool native) {
  MesaFigures f;
  auto q = [&](GLenum api, GLenum nat) { return query(target, native ? nat : api); };
  f.instructions = q(GL_PROGRAM_INSTRUCTIONS_ARB, GL_PROGRAM_NATIVE_INSTRUCTIONS_ARB);
  f.temporaries = q(GL_PROGRAM_TEMPORARIES_ARB, GL_PROGRAM_NATIVE_TEMPORARIES_ARB);
  f.parameters = q(GL_PROGRAM_PARAMETERS_ARB, GL_PROGRAM_NATIVE_PARAMETERS_ARB);
  f.attributes = q(GL_PROGRAM_ATTRIBS_ARB, GL_PROGRAM_NATIVE_ATTRIBS_ARB);
  f.address_registers =
      q(GL_PROGRAM_ADDRESS_REGISTERS_ARB, GL_PROGRAM_NATIVE_ADDRESS_REGISTERS_ARB);
  if (target == GL_FRAGMENT_PROGRAM_ARB) {
    f.alu = q(GL_PROGRAM_ALU_INSTRUCTIONS_ARB, GL_PROGRAM_NATIVE_ALU_INSTRUCTIONS_ARB);
    f.tex = q(GL_PROGRAM_TEX_INSTRUCTIONS_ARB, GL_PROGRAM_NATIVE_TEX_INSTRUCTIONS_ARB);
    f.indirections = q(GL_PROGRAM_TEX_INDIRECTIONS_ARB, GL_PROGRAM_NATIVE_TEX_INDIRECTIONS_ARB);
  }
  return f;
}

}  // namespace

MesaCounts mesa_counts(budget::ProgramKind kind, const std::string& source) {
  const GLenum target =
      kind == budget::ProgramKind::Vertex ? GL_VERTEX_PROGRAM_ARB : GL_FRAGMENT_PROGRAM_ARB;
  MesaCounts m;
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  m.renderer = renderer ? renderer : "";
  const ArbLoad load = load_arb_program(target, source);
  m.accepted = load.id != 0;
  m.error_offset = load.error_position;
  m.error = load.error;
  if (!m.accepted) return m;
  m.native = query_figures(target, true);
  m.api = query_figures(target, false);
  glDeleteProgramsARB(1, &load.id);
  return m;
}

}  // namespace lt::arbfp
