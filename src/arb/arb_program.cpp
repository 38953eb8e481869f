#include "arb/arb_program.h"

#include <algorithm>
#include <stdexcept>

namespace lt::arbfp {

ArbLoad load_arb_program(GLenum target, const std::string& source) {
  while (glGetError() != GL_NO_ERROR) {
  }
  ArbLoad out;
  glGenProgramsARB(1, &out.id);
  glBindProgramARB(target, out.id);
  glProgramStringARB(target, GL_PROGRAM_FORMAT_ASCII_ARB, static_cast<GLsizei>(source.size()),
                     source.c_str());
  glGetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &out.error_position);
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR || out.error_position != -1) {
    const char* msg = reinterpret_cast<const char*>(glGetString(GL_PROGRAM_ERROR_STRING_ARB));
    out.error = msg ? msg : "";
    glDeleteProgramsARB(1, &out.id);
    out.id = 0;
  }
  return out;
}

ArbProgram::ArbProgram(GLenum target, const std::string& source, const std::string& name)
    : target_(target) {
  const ArbLoad load = load_arb_program(target, source);
  id_ = load.id;
  if (!id_) {
    const GLint pos = load.error_position;
    const size_t at = pos >= 0 ? std::min(static_cast<size_t>(pos), source.size()) : 0;
    const size_t from = source.rfind('\n', at == 0 ? 0 : at - 1);
    const std::string line =
        source.substr(from == std::string::npos ? 0 : from + 1,
                      source.find('\n', at) - (from == std::string::npos ? 0 : from + 1));
    throw std::runtime_error("ARB program error in " + name + " at offset " + std::to_string(pos) +
                             " (\"" + line + "\"): " + load.error + "\n" + source);
  }
}

ArbProgram::~ArbProgram() {
  if (id_) glDeleteProgramsARB(1, &id_);
}

GLint ArbProgram::query(GLenum pname) const {
  bind();
  GLint v = -1;
  glGetProgramivARB(target_, pname, &v);
  return v;
}

}  // namespace lt::arbfp
