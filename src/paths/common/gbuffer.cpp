#include "paths/common/gbuffer.h"

#include <algorithm>

namespace lt {

Scene camera_relative_lights(const PathContext& ctx) {
  Scene s;
  s.file = ctx.scene.file;
  s.width = ctx.scene.width;
  s.height = ctx.scene.height;
  s.background = ctx.scene.background;
  s.camera = ctx.scene.camera;
  s.ambient_light = ctx.scene.ambient_light;
  s.materials = ctx.scene.materials;
  s.lights = ctx.scene.lights;
  for (Light& l : s.lights) l.position = ctx.geometry.to_camera_relative(l.position);
  return s;
}

GBuffer::GBuffer(const PathContext& ctx, const std::string& user)
    : ctx_(ctx),
      program_(gl::read_shader_source("legacy_shaders/glsl/gbuffer.vert"),
               gl::read_shader_source("legacy_shaders/glsl/gbuffer.frag"), "gbuffer"),
      rect_(ctx.geometry.covered_rect()),
      uv_target_(std::any_of(ctx.scene.materials.begin(), ctx.scene.materials.end(),
                             [](const Material& m) { return samples_uvs(m); })),
      thickness_read_(std::any_of(ctx.scene.materials.begin(), ctx.scene.materials.end(),
                                  [](const Material& m) {
                                    return m.translucency && m.translucency->thickness_source ==
                                                                 ThicknessSource::Vertex;
                                  })),
      target_(ctx.width, ctx.height, uv_target_ ? 4 : 3) {
  ctx.gl.require_extension("GL_ARB_texture_float", user);
  ctx.gl.require_extension("GL_ARB_draw_buffers", user);
}

void GBuffer::rasterise() {
  target_.bind();
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect_.x, rect_.y, rect_.width, rect_.height);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glUseProgram(program_.id());
  ctx_.geometry.load_matrices();
  for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
    glUniform1f(program_.uniform("u_material"), static_cast<float>(m.material));
    ctx_.geometry.draw(m);
  }
  glUseProgram(0);
  glDisable(GL_SCISSOR_TEST);  // the context is shared with the other paths of a session
  target_.unbind();
  target_.read(0, rect_, position_);
  target_.read(1, rect_, normal_);
  if (thickness_read_) target_.read(2, rect_, thickness_);
  if (uv_target_) target_.read(3, rect_, uv_);
  gl::check_error("reference G-buffer");
}

void GBuffer::append(size_t g, PixelRun& run) const {
  const size_t i = run.count++;
  for (int c = 0; c < 3; ++c) {
    run.position[c][i] = position_[g + c];
    run.normal[c][i] = normal_[g + c];
    run.thickness[c][i] = thickness_read_ ? thickness_[g + c] : 0.0f;
  }
  for (int c = 0; c < 2; ++c) run.uv[c][i] = uv_.empty() ? 0.0f : uv_[g + c];
}

void GBuffer::pad(PixelRun& run) {
  for (size_t i = run.count; i < padded_count(run.count, kPixelRunPadding); ++i) {
    for (int c = 0; c < 3; ++c) {
      run.position[c][i] = run.position[c][0];
      run.normal[c][i] = run.normal[c][0];
      run.thickness[c][i] = run.thickness[c][0];
    }
    for (int c = 0; c < 2; ++c) run.uv[c][i] = run.uv[c][0];
  }
}

std::vector<BuiltStage> GBuffer::stages() const {
  return {{uv_target_ ? "G-buffer: 4 x RGBA32F (position, normal + material, thickness, map UV)"
                      : "G-buffer: 3 x RGBA32F (position, normal + material, thickness)",
           "glsl-vertex", program_.vertex_source()},
          {"G-buffer fragment", "glsl-fragment", program_.fragment_source()}};
}

std::vector<int> material_per_pixel(const PathContext& ctx) {
  GBuffer g(ctx, "the material of each pixel");
  g.rasterise();
  std::vector<int> material(static_cast<size_t>(g.width()) * g.height(), -1);
  const int count = static_cast<int>(ctx.scene.materials.size());
  for (int gy = 0; gy < g.height(); ++gy) {
    for (int x = 0; x < g.width(); ++x) {
      if (!g.in_rect(x, gy)) continue;
      const size_t i = g.index(x, gy);
      const int m = g.material(i);
      // G-buffer rows count bottom-up, images top-down.
      if (g.covered(i) && m >= 0 && m < count)
        material[static_cast<size_t>(g.height() - 1 - gy) * g.width() + x] = m;
    }
  }
  return material;
}

std::vector<double> covered_pixels_by_material(const PathContext& ctx) {
  std::vector<double> pixels(ctx.scene.materials.size(), 0.0);
  for (int m : material_per_pixel(ctx)) {
    if (m >= 0) pixels[static_cast<size_t>(m)] += 1;
  }
  return pixels;
}

}  // namespace lt
