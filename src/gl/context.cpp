#include "gl/context.h"

#include <stdexcept>

namespace lt::gl {

Context::Context(int width, int height) : width_(width), height_(height) {
  const int attribs[] = {OSMESA_FORMAT,
                         OSMESA_RGBA,
                         OSMESA_DEPTH_BITS,
                         24,
                         OSMESA_STENCIL_BITS,
                         0,
                         OSMESA_ACCUM_BITS,
                         0,
                         OSMESA_PROFILE,
                         OSMESA_COMPAT_PROFILE,
                         OSMESA_CONTEXT_MAJOR_VERSION,
                         2,
                         OSMESA_CONTEXT_MINOR_VERSION,
                         1,
                         0};
  ctx_ = OSMesaCreateContextAttribs(attribs, nullptr);
  if (!ctx_) throw std::runtime_error("OSMesa: cannot create an RGBA8 + depth24 context");
  buffer_.assign(static_cast<size_t>(width) * height * 4, 0);
  if (!OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
    OSMesaDestroyContext(ctx_);
    throw std::runtime_error("OSMesa: cannot make the context current at " + std::to_string(width) +
                             "x" + std::to_string(height));
  }
  // OSMesa's default is y-up (bottom row first), the same as glReadPixels.
  const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  extensions_ = ext ? ext : "";
  if (extensions_.empty()) {
    // Core-style enumeration is the only way on some drivers.
    GLint n = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &n);
    for (GLint i = 0; i < n; ++i) {
      extensions_ += reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, i));
      extensions_ += ' ';
    }
  }
  extensions_ = " " + extensions_ + " ";
}

Context::~Context() {
  if (ctx_) OSMesaDestroyContext(ctx_);
}

bool Context::has_extension(const std::string& name) const {
  return extensions_.find(" " + name + " ") != std::string::npos;
}

void Context::require_extension(const std::string& name, const std::string& why) const {
  if (!has_extension(name)) {
    throw std::runtime_error("OSMesa context (" + renderer() + ") lacks " + name + " (needed for " +
                             why + ")");
  }
}

std::string Context::renderer() const {
  const char* r = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(r ? r : "?") + ", GL " + (v ? v : "?");
}

void check_error(const char* what) {
  const GLenum e = glGetError();
  if (e != GL_NO_ERROR) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04x", e);
    throw std::runtime_error(std::string("GL error ") + buf + " in " + what);
  }
}

}  // namespace lt::gl
