// RAII OSMesa context: an 8-bit RGBA colour buffer with a 24-bit depth buffer, the framebuffer of
// the low-end paths. Float render targets (the reference G-buffer) are FBOs on top of it.
#pragma once

#include <string>
#include <vector>

#include "gl/gl.h"

namespace lt::gl {

class Context {
 public:
  // Compatibility profile: the legacy paths need fixed-function state, ARB programs and GLSL 1.10.
  Context(int width, int height);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  bool has_extension(const std::string& name) const;
  // Throws std::runtime_error "OSMesa context lacks <name> (needed for <why>)".
  void require_extension(const std::string& name, const std::string& why) const;
  std::string renderer() const;

 private:
  OSMesaContext ctx_ = nullptr;
  int width_, height_;
  std::vector<unsigned char> buffer_;
  std::string extensions_;
};

// Throws std::runtime_error naming `what` and the GL error, if any is pending.
void check_error(const char* what);

}  // namespace lt::gl
