#include "paths/common/frame.h"

#include "gl/context.h"

namespace lt {

void begin_frame(const PathContext& ctx) {
  const glm::dvec3& bg = ctx.scene.background;
  glViewport(0, 0, ctx.width, ctx.height);
  glClearColor(static_cast<float>(bg.r), static_cast<float>(bg.g), static_cast<float>(bg.b), 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  ctx.geometry.load_matrices();
}

Image read_framebuffer(const gl::Context& gl) {
  Image img(gl.width(), gl.height());
  std::vector<unsigned char> px(img.pixel_count() * 4);
  glReadPixels(0, 0, gl.width(), gl.height(), GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  for (size_t i = 0; i < px.size(); ++i) img.rgba[i] = px[i] / 255.0f;
  flip_vertically(img);
  return img;
}

void begin_additive_passes() {
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
}

void end_additive_passes() {
  glDisable(GL_BLEND);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
}

}  // namespace lt
