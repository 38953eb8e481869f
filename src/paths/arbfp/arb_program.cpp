#include "paths/arbfp/arb_program.h"

#include <algorithm>
#include <stdexcept>

namespace lt::arbfp {

ArbProgram::ArbProgram(GLenum target, const std::string& source, const std::string& name)
    : target_(target) {
  while (glGetError() != GL_NO_ERROR) {
  }
  glGenProgramsARB(1, &id_);
  glBindProgramARB(target_, id_);
  glProgramStringARB(target_, GL_PROGRAM_FORMAT_ASCII_ARB, static_cast<GLsizei>(source.size()),
                     source.c_str());
  GLint pos = -1;
  glGetIntegerv(GL_PROGRAM_ERROR_POSITION_ARB, &pos);
  const GLenum err = glGetError();
  if (err != GL_NO_ERROR || pos != -1) {
    const char* msg = reinterpret_cast<const char*>(glGetString(GL_PROGRAM_ERROR_STRING_ARB));
    const size_t at = pos >= 0 ? std::min(static_cast<size_t>(pos), source.size()) : 0;
    const size_t from = source.rfind('\n', at == 0 ? 0 : at - 1);
    const std::string line =
        source.substr(from == std::string::npos ? 0 : from + 1,
                      source.find('\n', at) - (from == std::string::npos ? 0 : from + 1));
    glDeleteProgramsARB(1, &id_);
    throw std::runtime_error("ARB program error in " + name + " at offset " + std::to_string(pos) +
                             " (\"" + line + "\"): " + (msg ? msg : "") + "\n" + source);
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
