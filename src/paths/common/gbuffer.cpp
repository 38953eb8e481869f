#include "paths/common/gbuffer.h"

#include <algorithm>

namespace lt {

namespace {

// gbuffer.vert or gbuffer.frag with the varyings and the targets of `layout` alone.
std::string gbuffer_source(const std::string& file, const GBufferLayout& layout) {
  return gl::fill_template(gl::read_shader_source("legacy_shaders/glsl/" + file),
                           {{"DEFINES", layout.defines()}}, file);
}

}  // namespace

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

GBuffer::GBuffer(const PathContext& ctx, const std::string& user, GreyThickness grey)
    : ctx_(ctx),
      layout_(gbuffer_layout(ctx.scene, ctx.geometry, grey)),
      program_(gbuffer_source("gbuffer.vert", layout_), gbuffer_source("gbuffer.frag", layout_),
               "gbuffer"),
      rect_(ctx.geometry.covered_rect()),
      target_(ctx.width, ctx.height, layout_.targets()) {
  ctx.gl.require_extension("GL_ARB_texture_float", user);
  ctx.gl.require_extension("GL_ARB_draw_buffers", user);
}

void GBuffer::rasterise() {
  glEnable(GL_SCISSOR_TEST);
  glScissor(rect_.x, rect_.y, rect_.width, rect_.height);
  // Only the target that carries coverage is cleared: the others are read only at the pixels
  // it says a fragment covered this frame (shade_row; material_per_pixel reads target 0 alone).
  target_.clear_first_and_depth();
  glEnable(GL_DEPTH_TEST);
  glUseProgram(program_.id());
  ctx_.geometry.load_matrices();
  const GLint material_plus_one = program_.uniform("u_material_plus_one");
  for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
    glUniform1f(material_plus_one, static_cast<float>(m.material + 1));
    ctx_.geometry.draw(m);
  }
  glUseProgram(0);
  glDisable(GL_SCISSOR_TEST);  // the context is shared with the other paths of a session
  target_.unbind();
  target_.read(0, rect_, position_);
  target_.read(1, rect_, normal_);
  if (layout_.targets() == 3) target_.read(2, rect_, thickness_);
  gl::check_error("reference G-buffer");
}

void GBuffer::zero_thickness_lanes(PixelRun& run) {
  for (auto& channel : run.thickness) std::fill_n(channel, kPixelRunCapacity, 0.0f);
}

void GBuffer::zero_uv_lanes(PixelRun& run) {
  for (auto& channel : run.uv) std::fill_n(channel, kPixelRunCapacity, 0.0f);
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
  return {{"G-buffer: " + layout_.description(), "glsl-vertex", program_.vertex_source()},
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
      const int m = g.material(g.index(x, gy));
      // G-buffer rows count bottom-up, images top-down.
      if (m >= 0 && m < count)
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
