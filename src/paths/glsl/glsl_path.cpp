#include "paths/glsl/glsl_path.h"

#include <glm/gtc/type_ptr.hpp>
#include <sstream>

#include "gl/map_texture.h"
#include "gl/program.h"
#include "paths/common/first_frame_fragments.h"
#include "paths/common/frame.h"

namespace lt {

namespace {

std::string light_prefix(size_t i) {
  return "u_light" + std::to_string(i) + "_";
}

// The generated sources for one material.
struct GlslSources {
  std::string vertex, fragment;
};

GlslSources generate_glsl(const Scene& scene, const Material& material) {
  const bool translucent = material.translucency.has_value();
  const Translucency tr = material.translucency.value_or(Translucency{});
  bool any_point = false;
  std::ostringstream uniforms, calls;
  for (size_t i = 0; i < scene.lights.size(); ++i) {
    const Light& l = scene.lights[i];
    const std::string u = light_prefix(i);
    // The scale uniform exists only where a translucency term reads it.
    const std::string scale = translucent ? u + "scale" : "0.0";
    uniforms << "uniform vec3 " << u << "color;\n";
    if (translucent) uniforms << "uniform float " << u << "scale;\n";
    if (l.type == Light::Type::Directional) {
      uniforms << "uniform vec3 " << u << "to_light;  // -direction\n";
      calls << "  sum += light_term(N, V, " << u << "to_light, 1.0, " << u << "color, " << scale
            << ", T);\n";
    } else {
      any_point = true;
      uniforms << "uniform vec3 " << u << "position;\n"
               << "uniform vec3 " << u << "attenuation;  // kc, kl, kq\n";
      calls << "  {\n    vec3 L;\n    float att;\n    point_light(v_position, N, " << u
            << "position, " << u << "attenuation, L, att);\n    sum += light_term(N, V, L, att, "
            << u << "color, " << scale << ", T);\n  }\n";
    }
  }
  const bool vertex_thickness = translucent && tr.thickness_source == ThicknessSource::Vertex;
  const std::string defines =
      gl::glsl_define("LT_TRANSLUCENCY", translucent) +
      gl::glsl_define("LT_VERTEX_THICKNESS", vertex_thickness) +
      gl::glsl_define("LT_NORMALIZE_H", translucent && tr.normalize_distorted_light) +
      gl::glsl_define("LT_POWER_ZERO", translucent && tr.power == 0) +
      gl::glsl_define("LT_POINT_LIGHTS", any_point) +
      gl::glsl_define("LT_AMBIENT_LIGHT", scene.ambient_light != glm::dvec3(0)) +
      gl::glsl_define("LT_ORTHOGRAPHIC",
                      scene.camera.projection == Camera::Projection::Orthographic) +
      gl::glsl_define("LT_THICKNESS_MAP",
                      translucent && tr.thickness_source == ThicknessSource::Texture) +
      gl::glsl_define("LT_RAMP", translucent && tr.ramp != nullptr) +
      gl::glsl_define("LT_ALBEDO_MAP", material.albedo_map != nullptr);
  GlslSources s;
  s.vertex = gl::fill_template(gl::read_shader_source("legacy_shaders/glsl/translucency.vert"),
                               {{"DEFINES", defines}}, "translucency.vert");
  s.fragment = gl::fill_template(
      gl::read_shader_source("legacy_shaders/glsl/translucency.frag"),
      {{"DEFINES", defines}, {"LIGHT_UNIFORMS", uniforms.str()}, {"LIGHT_CALLS", calls.str()}},
      "translucency.frag");
  return s;
}

// The textures of the materials that have programs: the thickness map on unit 1 (its UVs are
// texture coordinate set 1, gl/scene_geometry.h), the ramp on unit 0, the albedo map on unit 2
// (read at the same UVs).
constexpr int kRampTextureUnit = 0, kMapTextureUnit = 1, kAlbedoTextureUnit = 2;
// GLSL 1.10 is the GL 2.0 class, whose parts filter fp16 but not fp32 textures: a float map or
// ramp is uploaded as half (gl/map_texture.h).
constexpr gl::MapTexelClass kTexelClass = gl::MapTexelClass::Fp16;
class MaterialTextures {
 public:
  MaterialTextures() = default;
  MaterialTextures(const PathContext& ctx,
                   const std::vector<std::unique_ptr<gl::GlslProgram>>& programs) {
    maps_.resize(programs.size());
    ramps_.resize(programs.size());
    albedo_maps_.resize(programs.size());
    for (size_t i = 0; i < programs.size(); ++i) {
      if (programs[i] && ctx.scene.materials[i].albedo_map) {
        albedo_maps_[i] = std::make_shared<gl::MapTexture>(
            ctx.gl, *ctx.scene.materials[i].albedo_map, kTexelClass);
      }
      if (!programs[i] || !ctx.scene.materials[i].translucency) continue;
      const Translucency& tr = *ctx.scene.materials[i].translucency;
      if (tr.thickness_map)
        maps_[i] = std::make_shared<gl::MapTexture>(ctx.gl, *tr.thickness_map, kTexelClass);
      if (tr.ramp) ramps_[i] = std::make_shared<gl::MapTexture>(ctx.gl, *tr.ramp, kTexelClass);
    }
  }
  void bind(int material) const {
    bind_unit(kMapTextureUnit, maps_[material].get());
    bind_unit(kRampTextureUnit, ramps_[material].get());
    bind_unit(kAlbedoTextureUnit, albedo_maps_[material].get());
  }
  void unbind() const {
    bind_unit(kMapTextureUnit, nullptr);
    bind_unit(kRampTextureUnit, nullptr);
    bind_unit(kAlbedoTextureUnit, nullptr);
  }
  void describe(const Scene& scene, std::vector<BuiltStage>& out) const {
    for (size_t i = 0; i < maps_.size(); ++i) {
      const std::string name = "material " + scene.materials[i].name;
      if (maps_[i]) {
        out.push_back(
            {name + ": thickness map, one texture2D on unit 1: " + maps_[i]->description(),
             "texture", ""});
      }
      if (ramps_[i]) {
        out.push_back({name + ": lobe ramp, one texture2D per light on unit 0 (replaces pow): " +
                           ramps_[i]->description(),
                       "texture", ""});
      }
      if (albedo_maps_[i]) {
        out.push_back({name + ": albedo map, one texture2D on unit 2 times the albedo: " +
                           albedo_maps_[i]->description(),
                       "texture", ""});
      }
    }
  }

 private:
  static void bind_unit(int unit, const gl::MapTexture* t) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, t ? t->id() : 0);
    glActiveTexture(GL_TEXTURE0);
  }
  // shared_ptr: the path moves this into place after building it.
  std::vector<std::shared_ptr<gl::MapTexture>> maps_, ramps_, albedo_maps_;
};

void set3(const gl::GlslProgram& p, const std::string& name, const glm::dvec3& v) {
  glUniform3f(p.uniform(name.c_str()), static_cast<float>(v.x), static_cast<float>(v.y),
              static_cast<float>(v.z));
}
void set1(const gl::GlslProgram& p, const std::string& name, double v) {
  glUniform1f(p.uniform(name.c_str()), static_cast<float>(v));
}

// The default draws into the 8-bit OSMesa framebuffer, as a port would. The `:f32` variant draws
// into an RGBA32F target instead, so the shader's own float arithmetic is measured without the
// output quantisation (whose floor alone is 0.5 LSB max and ~0.25 LSB mean against the float
// reference).
class GlslPath final : public Path {
 public:
  GlslPath(const PathContext& ctx, bool float_target)
      : ctx_(ctx), fragments_("glsl", ctx.geometry) {
    if (float_target) {
      ctx.gl.require_extension("GL_ARB_texture_float", "the glsl f32 target");
      target_ = std::make_unique<gl::FloatTarget>(ctx.width, ctx.height, 1);
    }
    // Only the materials some object uses get a program.
    programs_.resize(ctx.scene.materials.size());
    for (const gl::GpuMesh& m : ctx.geometry.meshes()) {
      if (programs_[m.material]) continue;
      const Material& mat = ctx.scene.materials[m.material];
      const GlslSources src = generate_glsl(ctx.scene, mat);
      auto p = std::make_unique<gl::GlslProgram>(src.vertex, src.fragment, "glsl:" + mat.name);
      set_uniforms(*p, mat);
      programs_[m.material] = std::move(p);
    }
    textures_ = MaterialTextures(ctx, programs_);
    gl::check_error("building glsl programs");
  }

  void frame() override {
    if (target_) target_->bind();
    begin_frame(ctx_);
    fragments_.begin();
    for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
      glUseProgram(programs_[m.material]->id());
      textures_.bind(m.material);
      ctx_.geometry.draw(m);
    }
    fragments_.end();
    textures_.unbind();
    glUseProgram(0);
    if (target_) target_->unbind();
  }

  Image result() override {
    if (!target_) return read_framebuffer(ctx_.gl);
    Image img(ctx_.width, ctx_.height);
    target_->read(0, img.rgba);
    flip_vertically(img);
    return img;
  }

  bool float_output() const override { return target_ != nullptr; }

  // Mesa reports no instruction count for GLSL (GL_ARB_fragment_program's NATIVE queries cover
  // only ARB programs), and counting source operators would not be what runs.
  WorkModel work() const override {
    return {{}, {}, {}, "GLSL: the driver reports no instruction count"};
  }

  std::vector<BuiltStage> stages() const override {
    std::vector<BuiltStage> out;
    for (size_t i = 0; i < programs_.size(); ++i) {
      if (!programs_[i]) continue;
      const std::string name = "material " + ctx_.scene.materials[i].name;
      out.push_back({name + ": vertex shader", "glsl-vertex", programs_[i]->vertex_source()});
      out.push_back({name + ": fragment shader", "glsl-fragment", programs_[i]->fragment_source()});
    }
    textures_.describe(ctx_.scene, out);
    return out;
  }

 private:
  void set_uniforms(const gl::GlslProgram& p, const Material& mat) {
    const Scene& s = ctx_.scene;
    glUseProgram(p.id());
    set3(p, "u_albedo", mat.albedo);
    if (mat.albedo_map) glUniform1i(p.uniform("u_albedo_map"), kAlbedoTextureUnit);
    set3(p, "u_ambient_light", s.ambient_light);
    set3(p, "u_view_dir", -s.camera.forward());
    if (mat.translucency) {
      const Translucency& tr = *mat.translucency;
      set1(p, "u_power", tr.power);
      set1(p, "u_distortion", tr.distortion);
      set1(p, "u_lt_ambient", tr.ambient);
      // Vertex thickness is multiplied by the tint in the shader; a constant is premultiplied.
      set3(p, "u_thickness",
           tr.thickness_source == ThicknessSource::Constant ? tr.thickness * tr.tint : tr.tint);
      if (tr.thickness_source == ThicknessSource::Texture) {
        glUniform1i(p.uniform("u_thickness_map"), kMapTextureUnit);
      }
      if (tr.ramp) glUniform1i(p.uniform("u_ramp"), kRampTextureUnit);
    }
    for (size_t i = 0; i < s.lights.size(); ++i) {
      const Light& l = s.lights[i];
      const std::string u = light_prefix(i);
      set3(p, u + "color", l.color);
      set1(p, u + "scale", l.translucency_scale);
      set3(p, u + "to_light", -l.direction);
      set3(p, u + "position", ctx_.geometry.to_camera_relative(l.position));
      set3(p, u + "attenuation", glm::dvec3(l.kc, l.kl, l.kq));
    }
    glUseProgram(0);
  }

  PathContext ctx_;
  FirstFrameFragments fragments_;  // the warning of an empty frame
  std::unique_ptr<gl::FloatTarget> target_;
  std::vector<std::unique_ptr<gl::GlslProgram>> programs_;
  MaterialTextures textures_;
};

// The variants differ in the target alone (the shaders are the same).
enum class GlslTarget { Unorm8, Float32 };

class GlslInfo final : public ListedPathInfo<GlslTarget> {
 public:
  GlslInfo()
      : ListedPathInfo(
            "glsl", "per-pixel GLSL 1.10 shaders, exact pow, float arithmetic, 8-bit framebuffer",
            {{{"pow=exact", "pow() with 0^0 guarded, 8-bit framebuffer"}, GlslTarget::Unorm8},
             {{"pow=exact:f32", "the same shaders into an RGBA32F target: shader precision alone",
               VariantRun::Story},
              GlslTarget::Float32}}) {}
  std::unique_ptr<Path> build(const PathContext& ctx, const GlslTarget& target) const override {
    return std::make_unique<GlslPath>(ctx, target == GlslTarget::Float32);
  }
};

}  // namespace

const PathInfo& glsl_path_info() {
  static const GlslInfo info;
  return info;
}

}  // namespace lt
