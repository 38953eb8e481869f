// GLSL program and float render-target helpers.
#pragma once

#include <string>
#include <vector>

#include "gl/gl.h"
#include "gl/pixel_rect.h"

namespace lt::gl {

// Compiles and links a GLSL 1.10 program. On failure throws std::runtime_error with the info log
// and the offending source, numbered, so a template bug is found at once.
class GlslProgram {
 public:
  GlslProgram(const std::string& vertex_source, const std::string& fragment_source,
              const std::string& name);
  ~GlslProgram();
  GlslProgram(const GlslProgram&) = delete;
  GlslProgram& operator=(const GlslProgram&) = delete;

  GLuint id() const { return program_; }
  // -1 when the uniform was optimised away or is absent (glUniform ignores -1).
  GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }
  const std::string& vertex_source() const { return vs_; }
  const std::string& fragment_source() const { return fs_; }

 private:
  void release();  // deletes what exists of the program and its shaders
  GLuint program_ = 0, vertex_ = 0, fragment_ = 0;
  std::string vs_, fs_;
};

// An FBO with `count` RGBA32F colour attachments and a 24-bit depth buffer: the G-buffer.
class FloatTarget {
 public:
  FloatTarget(int width, int height, int count);
  ~FloatTarget();
  FloatTarget(const FloatTarget&) = delete;
  FloatTarget& operator=(const FloatTarget&) = delete;

  void bind() const;    // binds and selects all draw buffers
  void unbind() const;  // back to the OSMesa framebuffer
  // Clears attachment 0 to 0 and the depth buffer (within the scissor when it is on), and leaves
  // the other attachments as they are; bound, with all draw buffers selected again after. Each
  // cleared target is a pass over its pixels: a G-buffer that keeps coverage in attachment 0
  // never reads the others where nothing was drawn.
  void clear_first_and_depth() const;
  // Reads attachment `index` as RGBA float, bottom row first: the whole target, or `rect`.
  void read(int index, std::vector<float>& out) const;
  void read(int index, const PixelRect& rect, std::vector<float>& out) const;

 private:
  int width_, height_;
  GLuint fbo_ = 0, depth_ = 0;
  std::vector<GLuint> textures_;

  void select_all_draw_buffers() const;
};

// Replaces every `{{KEY}}` in `text` by its value; throws if a placeholder is left unreplaced,
// so a template and its generator cannot drift apart silently.
std::string fill_template(std::string text,
                          const std::vector<std::pair<std::string, std::string>>& values,
                          const std::string& name);

// `#define NAME 1` or `#define NAME 0` and a newline: a template's switches, tested with `#if`.
std::string glsl_define(const std::string& name, bool on);

// A file under legacy_shaders/ or combiners/, embedded at build time (core/embedded.h).
std::string read_shader_source(const std::string& relative_path);

}  // namespace lt::gl
