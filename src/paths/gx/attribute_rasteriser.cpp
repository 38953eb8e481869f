#include "paths/gx/attribute_rasteriser.h"

#include "core/error.h"
#include "gl/context.h"

namespace lt::gx {

namespace {

// Generic attribute slots: 0 is gl_Vertex in the compatibility profile.
constexpr GLuint kColor0Slot = 1, kColor1Slot = 2, kTexCoordSlot = 3;

std::string shader(const std::string& file, int texgens, bool fragment) {
  std::string inputs, outputs, assigns, writes;
  for (int i = 0; i < texgens; ++i) {
    const std::string n = std::to_string(i);
    if (fragment) {
      inputs += "in vec3 v_tc" + n + ";\n";
      writes += "  gl_FragData[" + std::to_string(3 + i) + "] = vec4(v_tc" + n + ", 0.0);\n";
    } else {
      inputs += "in vec3 a_tc" + n + ";\n";
      outputs += "out vec3 v_tc" + n + ";\n";
      assigns += "  v_tc" + n + " = a_tc" + n + ";\n";
    }
  }
  if (fragment)
    return gl::fill_template(gl::read_shader_source(file),
                             {{"TEXCOORD_INPUTS", inputs}, {"TEXCOORD_WRITES", writes}}, file);
  return gl::fill_template(
      gl::read_shader_source(file),
      {{"TEXCOORD_INPUTS", inputs}, {"TEXCOORD_OUTPUTS", outputs}, {"TEXCOORD_ASSIGNS", assigns}},
      file);
}

// A GX cull mode as GL face culling. GL's front faces are counter-clockwise in window
// coordinates (y up), which GX's setup unit calls back faces: GX_CULL_BACK removes GL's front
// faces and GX_CULL_FRONT GL's back faces (gx_state.h, [DSW Clipper.cpp CullTest]).
void set_cull_mode(u8 gx_mode) {
  if (gx_mode == kCullNone) {
    glDisable(GL_CULL_FACE);
    return;
  }
  glEnable(GL_CULL_FACE);
  glFrontFace(GL_CCW);
  glCullFace(gx_mode == kCullBack ? GL_FRONT : gx_mode == kCullFront ? GL_BACK : GL_FRONT_AND_BACK);
}

}  // namespace

AttributeRasteriser::AttributeRasteriser(const PathContext& ctx, int texgens)
    : ctx_(ctx), texgens_(texgens), target_(ctx.width, ctx.height, 3 + texgens) {
  LT_CHECK(texgens >= 0 && texgens <= kRasterisedTexGens, "too many texgens to rasterise");
  ctx.gl.require_extension("GL_ARB_texture_float", "the gx path's rasteriser");
  ctx.gl.require_extension("GL_ARB_draw_buffers", "the gx path's rasteriser");
  const std::string vs = shader("legacy_shaders/glsl/gx_attributes.vert", texgens, false);
  const std::string fs = shader("legacy_shaders/glsl/gx_attributes.frag", texgens, true);
  program_ = std::make_unique<gl::GlslProgram>(vs, fs, "gx attributes");
  glBindAttribLocation(program_->id(), kColor0Slot, "a_color0");
  glBindAttribLocation(program_->id(), kColor1Slot, "a_color1");
  for (int i = 0; i < texgens; ++i)
    glBindAttribLocation(program_->id(), kTexCoordSlot + static_cast<GLuint>(i),
                         ("a_tc" + std::to_string(i)).c_str());
  glLinkProgram(program_->id());  // the bindings take effect at link
  for (size_t i = 0; i < ctx.geometry.meshes().size(); ++i) {
    std::vector<GLuint> b(static_cast<size_t>(2 + texgens));
    glGenBuffers(static_cast<GLsizei>(b.size()), b.data());
    buffers_.push_back(std::move(b));
  }
  texcoords_.resize(static_cast<size_t>(texgens));
  gl::check_error("building the gx rasteriser");
}

AttributeRasteriser::~AttributeRasteriser() {
  for (auto& b : buffers_) glDeleteBuffers(static_cast<GLsizei>(b.size()), b.data());
}

void AttributeRasteriser::rasterise(const std::vector<const VertexOutputs*>& outputs,
                                    const std::vector<u8>& cull_modes) {
  target_.bind();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glUseProgram(program_->id());
  ctx_.geometry.load_matrices();
  const auto& meshes = ctx_.geometry.meshes();
  std::vector<float> color0, color1, tc;
  for (size_t i = 0; i < meshes.size(); ++i) {
    const gl::GpuMesh& mesh = meshes[i];
    const VertexOutputs* out = outputs[i];
    const size_t n = mesh.vertex_count;
    color0.assign(n * 4, 0.0f);
    color1.assign(n * 4, 0.0f);
    if (out) {
      for (size_t v = 0; v < n; ++v) {
        for (int c = 0; c < 4; ++c) {
          color0[v * 4 + c] = out->colors[v][0][c];
          color1[v * 4 + c] = out->colors[v][1][c];
        }
      }
    }
    const auto& b = buffers_[i];
    gl::stream_array_buffer(b[0], color0);
    gl::stream_array_buffer(b[1], color1);
    for (int g = 0; g < texgens_; ++g) {
      tc.assign(n * 3, 0.0f);
      if (out && g < out->num_texgens) {
        for (size_t v = 0; v < n; ++v) {
          for (int c = 0; c < 3; ++c) tc[v * 3 + c] = out->texcoords[v][static_cast<size_t>(g)][c];
        }
      }
      gl::stream_array_buffer(b[static_cast<size_t>(2 + g)], tc);
    }
    glUniform1f(program_->uniform("u_material"), static_cast<float>(mesh.material));
    set_cull_mode(cull_modes[i]);
    ctx_.geometry.bind(mesh);
    glBindBuffer(GL_ARRAY_BUFFER, b[0]);
    glEnableVertexAttribArray(kColor0Slot);
    glVertexAttribPointer(kColor0Slot, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, b[1]);
    glEnableVertexAttribArray(kColor1Slot);
    glVertexAttribPointer(kColor1Slot, 4, GL_FLOAT, GL_FALSE, 0, nullptr);
    for (int g = 0; g < texgens_; ++g) {
      const GLuint slot = kTexCoordSlot + static_cast<GLuint>(g);
      glBindBuffer(GL_ARRAY_BUFFER, b[static_cast<size_t>(2 + g)]);
      glEnableVertexAttribArray(slot);
      glVertexAttribPointer(slot, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    glDisableVertexAttribArray(kColor0Slot);
    glDisableVertexAttribArray(kColor1Slot);
    for (int g = 0; g < texgens_; ++g)
      glDisableVertexAttribArray(kTexCoordSlot + static_cast<GLuint>(g));
    ctx_.geometry.unbind();
  }
  glDisable(GL_CULL_FACE);
  glUseProgram(0);
  target_.unbind();
  target_.read(0, colors_[0]);
  target_.read(1, colors_[1]);
  target_.read(2, meta_);
  for (int g = 0; g < texgens_; ++g) target_.read(3 + g, texcoords_[static_cast<size_t>(g)]);
  gl::check_error("gx rasteriser");
}

}  // namespace lt::gx
