// An ARB_vertex_program / ARB_fragment_program object: loads assembly text and reports the
// parser's position and message on failure, so a generator bug names the line at once.
#pragma once

#include <string>

#include "gl/gl.h"

namespace lt::arbfp {

// What glProgramStringARB made of a text: the program object, or Mesa's error (the byte offset
// of GL_PROGRAM_ERROR_POSITION_ARB and GL_PROGRAM_ERROR_STRING_ARB). Leaves the program bound.
struct ArbLoad {
  GLuint id = 0;  // 0 when refused (the object is deleted)
  GLint error_position = -1;
  std::string error;
};
ArbLoad load_arb_program(GLenum target, const std::string& source);

class ArbProgram {
 public:
  // `target` is GL_VERTEX_PROGRAM_ARB or GL_FRAGMENT_PROGRAM_ARB. Throws std::runtime_error with
  // GL_PROGRAM_ERROR_STRING_ARB and the source around GL_PROGRAM_ERROR_POSITION_ARB.
  ArbProgram(GLenum target, const std::string& source, const std::string& name);
  ~ArbProgram();
  ArbProgram(const ArbProgram&) = delete;
  ArbProgram& operator=(const ArbProgram&) = delete;

  GLuint id() const { return id_; }
  GLenum target() const { return target_; }
  void bind() const { glBindProgramARB(target_, id_); }
  // glGetProgramivARB of this program (binds it), e.g. GL_PROGRAM_ALU_INSTRUCTIONS_ARB.
  GLint query(GLenum pname) const;

 private:
  GLenum target_;
  GLuint id_ = 0;
};

}  // namespace lt::arbfp
