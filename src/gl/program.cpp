#include "gl/program.h"

#include <sstream>
#include <stdexcept>

#include "core/embedded.h"
#include "core/error.h"
#include "gl/context.h"

namespace lt::gl {

namespace {
std::string numbered(const std::string& src) {
  std::istringstream in(src);
  std::ostringstream out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) out << n << ": " << line << "\n";
  return out.str();
}

GLuint compile(GLenum type, const std::string& src, const std::string& name) {
  GLuint s = glCreateShader(type);
  const char* p = src.c_str();
  glShaderSource(s, 1, &p, nullptr);
  glCompileShader(s);
  GLint ok = 0;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    char log[4096];
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    glDeleteShader(s);
    throw std::runtime_error("GLSL compile error in " + name +
                             (type == GL_VERTEX_SHADER ? " (vertex)" : " (fragment)") + ": " + log +
                             "\n" + numbered(src));
  }
  return s;
}
}  // namespace

GlslProgram::GlslProgram(const std::string& vs, const std::string& fs, const std::string& name)
    : vs_(vs), fs_(fs) {
  // A constructor that throws runs no destructor: every object made so far is released here
  // before the error leaves (a failed fragment compile or link used to leak the rest).
  try {
    vertex_ = compile(GL_VERTEX_SHADER, vs, name);
    fragment_ = compile(GL_FRAGMENT_SHADER, fs, name);
    program_ = glCreateProgram();
    glAttachShader(program_, vertex_);
    glAttachShader(program_, fragment_);
    glLinkProgram(program_);
    GLint ok = 0;
    glGetProgramiv(program_, GL_LINK_STATUS, &ok);
    if (!ok) {
      char log[4096];
      glGetProgramInfoLog(program_, sizeof log, nullptr, log);
      throw std::runtime_error("GLSL link error in " + name + ": " + log);
    }
  } catch (...) {
    release();
    throw;
  }
}

GlslProgram::~GlslProgram() {
  release();
}

void GlslProgram::release() {
  if (program_) glDeleteProgram(program_);
  if (vertex_) glDeleteShader(vertex_);
  if (fragment_) glDeleteShader(fragment_);
  program_ = vertex_ = fragment_ = 0;
}

FloatTarget::FloatTarget(int width, int height, int count) : width_(width), height_(height) {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  textures_.resize(count);
  glGenTextures(count, textures_.data());
  for (int i = 0; i < count; ++i) {
    glBindTexture(GL_TEXTURE_2D, textures_[i]);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, width, height, 0, GL_RGBA, GL_FLOAT, nullptr);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + i, GL_TEXTURE_2D, textures_[i],
                           0);
  }
  glBindTexture(GL_TEXTURE_2D, 0);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("float render target (RGBA32F x" + std::to_string(count) +
                             ") is incomplete on this OSMesa");
  }
  check_error("creating float render target");
}

FloatTarget::~FloatTarget() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &depth_);
  glDeleteTextures(static_cast<GLsizei>(textures_.size()), textures_.data());
}

void FloatTarget::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  select_all_draw_buffers();
  glViewport(0, 0, width_, height_);
}

void FloatTarget::select_all_draw_buffers() const {
  std::vector<GLenum> bufs(textures_.size());
  for (size_t i = 0; i < bufs.size(); ++i) bufs[i] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(i);
  glDrawBuffers(static_cast<GLsizei>(bufs.size()), bufs.data());
}

void FloatTarget::clear_first_and_depth() const {
  bind();
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  select_all_draw_buffers();
}

void FloatTarget::unbind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void FloatTarget::read(int index, std::vector<float>& out) const {
  read(index, PixelRect{0, 0, width_, height_}, out);
}

void FloatTarget::read(int index, const PixelRect& rect, std::vector<float>& out) const {
  out.resize(static_cast<size_t>(rect.width) * rect.height * 4);
  if (out.empty()) return;
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glReadBuffer(GL_COLOR_ATTACHMENT0 + index);
  glReadPixels(rect.x, rect.y, rect.width, rect.height, GL_RGBA, GL_FLOAT, out.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
}

std::string fill_template(std::string text,
                          const std::vector<std::pair<std::string, std::string>>& values,
                          const std::string& name) {
  for (const auto& [key, value] : values) {
    const std::string token = "{{" + key + "}}";
    for (size_t pos; (pos = text.find(token)) != std::string::npos;) {
      text.replace(pos, token.size(), value);
    }
  }
  const size_t left = text.find("{{");
  if (left != std::string::npos) {
    throw std::runtime_error("template " + name + ": unreplaced placeholder " +
                             text.substr(left, text.find("}}", left) - left + 2));
  }
  return text;
}

std::string glsl_define(const std::string& name, bool on) {
  return "#define " + name + (on ? " 1\n" : " 0\n");
}

std::string read_shader_source(const std::string& relative_path) {
  const auto& table = embedded::sources();
  const auto it = table.find(relative_path);
  LT_CHECK(it != table.end(), "no embedded program source " + relative_path);
  return it->second;
}

}  // namespace lt::gl
