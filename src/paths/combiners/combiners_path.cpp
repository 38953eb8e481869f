#include "paths/combiners/combiners_path.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "core/stopwatch.h"
#include "gl/context.h"
#include "gl/map_texture.h"
#include "gl/program.h"
#include "model/translucency.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/combiners/cube_lobe.h"
#include "paths/combiners/lobe_table.h"
#include "paths/combiners/map_stage.h"
#include "paths/combiners/texgen_matrix.h"
#include "paths/combiners/vertex_terms.h"
#include "paths/common/first_frame_fragments.h"
#include "paths/common/frame.h"

namespace lt {

const char* program_file(PassKind kind) {
  switch (kind) {
    case PassKind::DiffuseOnly:
      return "diffuse_only.comb";
    case PassKind::LobeVertex:
      return "lobe_vertex.comb";
    case PassKind::LobeTexgen:
      return "lobe_texgen.comb";
    case PassKind::LobeCube:
      return "lobe_cube.comb";
    case PassKind::LobeCubeFull:
      return "lobe_cube_full.comb";
    case PassKind::LobeVertexMap:
      return "lobe_vertex_map.comb";
    case PassKind::AlbedoModulate:
      return "albedo_modulate.comb";
  }
  return "";
}

namespace {

// Whether lobe=cube can bake `light`'s lobe for `m`: a directional light (the cube is of the
// normal alone), and a lobe the cube holds: lobe_cube_full.comb (constant thickness) holds any in
// rgb, lobe_cube.comb one channel in alpha (t^p, or a grey ramp).
bool cube_holds_lobe(const Material& m, const Light& light) {
  const Translucency& tr = *m.translucency;
  return light.type == Light::Type::Directional &&
         (tr.thickness_source == ThicknessSource::Constant || !tr.ramp || tr.ramp->grey);
}

}  // namespace

std::vector<CombinerMaterialPlan> plan_combiners(const Scene& scene, CombinersVariant variant) {
  std::vector<CombinerMaterialPlan> plans(scene.materials.size());
  for (const SceneObject& o : scene.objects) plans[o.material].used = true;
  for (size_t i = 0; i < plans.size(); ++i) {
    CombinerMaterialPlan& p = plans[i];
    const Material& m = scene.materials[i];
    p.material = static_cast<int>(i);
    if (!m.translucency || scene.lights.empty()) {
      p.pass_kinds = {PassKind::DiffuseOnly};
    } else {
      // One pass per light: the lobe needs att*T of its own light in the primary colour, and a
      // vertex has one primary colour (see combiners/README.md, "Why one pass per light").
      const bool texgen = variant == CombinersVariant::TTexgen && texgen_applicable(scene, m);
      for (const Light& l : scene.lights) {
        if (samples_thickness_map(m)) {
          // The map is a texture stage of its own, whatever the variant (map_stage.h).
          p.pass_kinds.push_back(PassKind::LobeVertexMap);
        } else if (variant == CombinersVariant::LobeCube && cube_holds_lobe(m, l)) {
          // Constant thickness: the whole term depends on N only and fits in the cube's rgb.
          const bool constant = m.translucency->thickness_source == ThicknessSource::Constant;
          p.pass_kinds.push_back(constant ? PassKind::LobeCubeFull : PassKind::LobeCube);
        } else {
          p.pass_kinds.push_back(texgen ? PassKind::LobeTexgen : PassKind::LobeVertex);
        }
      }
    }
    // Last, once the framebuffer holds the whole term (combiners/albedo_modulate.comb).
    if (m.albedo_map) p.pass_kinds.push_back(PassKind::AlbedoModulate);
    for (PassKind k : p.pass_kinds) {
      if (!p.programs.count(k))
        p.programs.emplace(k, combiners::load_combiner_program(program_file(k)));
    }
  }
  return plans;
}

namespace {

GLuint make_buffer() {
  GLuint b = 0;
  glGenBuffers(1, &b);
  return b;
}

// " (lobe ramp r.png: GL_RGB8 1D, 8 texels at u = t)" for `info`; nothing for t^p.
std::string describe_ramp(const Translucency& tr, const LobeTable& table) {
  if (!tr.ramp) return "";
  return " (lobe ramp " + tr.ramp->file.filename().string() + ": " +
         (table.channels == 3 ? "GL_RGB8" : "GL_LUMINANCE8") + " 1D, " +
         std::to_string(table.width) + " texels at u = t)";
}

class CombinersPath final : public Path {
 public:
  CombinersPath(const PathContext& ctx, CombinersVariant variant)
      : ctx_(ctx),
        fragments_("combiners", ctx.geometry),
        variant_(variant),
        plans_(plan_combiners(ctx.scene, variant)) {
    const Scene& s = ctx.scene;
    // A 1x1 white texture: bound by stages that sample nothing, so GL runs their environment.
    glGenTextures(1, &white_);
    glBindTexture(GL_TEXTURE_2D, white_);
    const unsigned char white[4] = {255, 255, 255, 255};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);

    tables_.resize(s.materials.size());
    table_textures_.resize(s.materials.size(), 0);
    maps_.resize(s.materials.size());
    albedo_maps_.resize(s.materials.size());
    map_tables_.resize(s.materials.size());
    cubes_.assign(s.materials.size(), std::vector<CubeLobe>(s.lights.size()));
    for (const CombinerMaterialPlan& p : plans_) {
      const Material& m = s.materials[p.material];
      // GL 1.3 parts have no sRGB textures: the decoded linear colour in 8 bits (map_texture.h).
      if (p.used && m.albedo_map) {
        albedo_maps_[p.material] =
            std::make_unique<gl::MapTexture>(ctx.gl, *m.albedo_map, gl::MapTexelClass::Unorm8);
      }
      if (!p.used || !m.translucency) continue;
      // 8-bit texels: what a GL 1.3 (or Wii I8) texture holds: t^p, or the material's ramp.
      tables_[p.material] = lobe_table(*m.translucency);
      table_textures_[p.material] = upload_lobe_table(tables_[p.material]);
      if (samples_thickness_map(m)) {
        // Per light: its (lobe s + a) / (gain s + a), and the map (map_stage.h).
        maps_[p.material] = std::make_unique<gl::MapTexture>(ctx.gl, *m.translucency->thickness_map,
                                                             gl::MapTexelClass::Unorm8);
        for (const Light& l : s.lights)
          map_tables_[p.material].push_back(upload_lobe_table(map_lobe_table(*m.translucency, l)));
      }
      for (int pass = 0; pass < p.passes(); ++pass) {
        if (!uses_cube(p.kind(pass))) continue;
        const auto t0 = std::chrono::steady_clock::now();
        cubes_[p.material][static_cast<size_t>(pass)] =
            build_cube_lobe(ctx_.scene, ctx_.geometry.origin(), p.material,
                            static_cast<size_t>(pass), p.kind(pass) == PassKind::LobeCubeFull);
        cube_seconds_ += seconds_since(t0);
      }
    }
    for (size_t i = 0; i < ctx.geometry.meshes().size(); ++i) {
      buffers_.push_back({make_buffer(), make_buffer(), make_buffer()});
    }
    gl::check_error("building the combiners path");
  }

  ~CombinersPath() override {
    for (const auto& b : buffers_) glDeleteBuffers(3, b.data());
    for (GLuint t : table_textures_) {
      if (t) glDeleteTextures(1, &t);
    }
    for (const auto& per_light : map_tables_) {
      for (GLuint t : per_light) glDeleteTextures(1, &t);
    }
    for (const auto& per_light : cubes_) {
      for (const CubeLobe& c : per_light) {
        if (c.texture) glDeleteTextures(1, &c.texture);
      }
    }
    glDeleteTextures(1, &white_);
  }

  void frame() override {
    const auto t0 = std::chrono::steady_clock::now();
    const auto& meshes = ctx_.geometry.meshes();
    std::vector<VertexTerms> terms(meshes.size());
    for (size_t i = 0; i < meshes.size(); ++i)
      terms[i] = vertex_terms(ctx_.scene, ctx_.geometry.origin(), i, table_of(i));
    cpu_seconds_ = seconds_since(t0);

    begin_frame(ctx_);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glDisable(GL_LIGHTING);
    fragments_.begin();

    int max_passes = 0;
    for (const gl::GpuMesh& m : meshes)
      max_passes = std::max(max_passes, plans_[m.material].passes());
    for (int pass = 0; pass < max_passes; ++pass) {
      // Later passes add one light each. Same vertices, same fixed-function transform: the
      // depths repeat exactly (GL's invariance rule), so EQUAL keeps pass 0's visible fragments.
      if (pass == 1) begin_additive_passes();
      for (size_t i = 0; i < meshes.size(); ++i) {
        if (pass < plans_[meshes[i].material].passes()) draw_pass(i, pass, terms[i]);
      }
    }
    passes_drawn_ = max_passes;
    end_additive_passes();
    fragments_.end();
    combiners::reset_texture_state(combiners::kMaxStages);
    gl::check_error("combiners frame");
  }

  Image result() override { return read_framebuffer(ctx_.gl); }

  std::string cost() const override {
    size_t stages = 0;
    int passes = 0;
    for (const CombinerMaterialPlan& p : plans_) {
      if (!p.used) continue;
      passes = std::max(passes, p.passes());
      for (int pass = 0; pass < p.passes(); ++pass) {
        stages = std::max(stages, p.program(pass).stages.size());
      }
    }
    return std::to_string(stages) + (stages == 1 ? " stage" : " stages") + " a pass, " +
           std::to_string(passes) + (passes == 1 ? " pass" : " passes");
  }

  // A combiner stage runs once a covered pixel in each pass the material is drawn in; on the CPU,
  // vertex_terms evaluates every light once a vertex (t, attenuation, diffuse, thickness).
  WorkModel work() const override {
    WorkModel w{"combiner stage", "CPU light evaluation", {}, {}};
    w.by_material.resize(plans_.size());
    for (const CombinerMaterialPlan& p : plans_) {
      if (!p.used) continue;
      double stages = 0;
      for (int pass = 0; pass < p.passes(); ++pass)
        stages += static_cast<double>(p.program(pass).stages.size());
      w.by_material[static_cast<size_t>(p.material)] = {
          stages, static_cast<double>(ctx_.scene.lights.size())};
    }
    return w;
  }

  std::vector<BuiltStage> stages() const override {
    std::vector<BuiltStage> out;
    for (const CombinerMaterialPlan& p : plans_) {
      if (!p.used) continue;
      const std::string material = "material " + ctx_.scene.materials[p.material].name;
      for (int pass = 0; pass < p.passes(); ++pass) {
        const PassKind kind = p.kind(pass);
        const std::string name = program_file(kind);
        std::string note;
        if (variant_ == CombinersVariant::TTexgen && kind == PassKind::LobeVertex) {
          note =
              " (texgen not applicable: needs directional lights, an orthographic camera and "
              "unnormalised H; t computed per vertex on the CPU)";
        }
        if (variant_ == CombinersVariant::LobeCube && kind == PassKind::LobeVertex) {
          note = ctx_.scene.lights[static_cast<size_t>(pass)].type == Light::Type::Point
                     ? " (point light: no cube, t per vertex)"
                     : " (rgb lobe ramp with per-vertex thickness: the cube's alpha holds one "
                       "channel; t per vertex)";
        }
        if (kind == PassKind::AlbedoModulate) {
          note = " (albedo map on unit 0: " +
                 albedo_maps_[static_cast<size_t>(p.material)]->description() +
                 "; blend GL_DST_COLOR, GL_ZERO over the passes before)";
        }
        if (kind == PassKind::LobeVertexMap) {
          note = " (thickness map on unit 1: " +
                 maps_[static_cast<size_t>(p.material)]->description() +
                 "; t per vertex whatever the variant)";
        }
        if (uses_cube(kind)) {
          const CubeLobe& c = cubes_[p.material][static_cast<size_t>(pass)];
          const bool ramp =
              ctx_.scene.materials[static_cast<size_t>(p.material)].translucency->ramp != nullptr;
          note = " (cube " + std::to_string(kCombinerCubeSize) + "^2 x 6, RGBA8" +
                 (c.constant_clamped ? "; albedo*color*g > 4 clamped" : "") +
                 (ramp ? "; the lobe ramp baked in" : "") + ")";
        } else if (kind != PassKind::DiffuseOnly && kind != PassKind::AlbedoModulate) {
          const size_t m = static_cast<size_t>(p.material);
          note += describe_ramp(*ctx_.scene.materials[m].translucency, tables_[m]);
        }
        out.push_back({material + ", pass " + std::to_string(pass) + ": combiners/" + name + ", " +
                           std::to_string(p.program(pass).stages.size()) + " stages" + note,
                       "combiners", gl::read_shader_source("combiners/" + name)});
      }
    }
    out.push_back(
        {"per-vertex terms on the CPU (t, att*T, diffuse), streamed each frame", "cpu", ""});
    return out;
  }

  FrameStats frame_stats() const override {
    FrameStats s;
    s.cpu_vertex_seconds = cpu_seconds_;
    s.passes = passes_drawn_;
    if (variant_ == CombinersVariant::LobeCube) s.cube_rebuild_seconds = cube_seconds_;
    return s;
  }

 private:
  void draw_pass(size_t object, int pass, const VertexTerms& vt) {
    const Scene& s = ctx_.scene;
    const gl::GpuMesh& mesh = ctx_.geometry.meshes()[object];
    const CombinerMaterialPlan& plan = plans_[static_cast<size_t>(mesh.material)];
    const PassKind kind = plan.kind(pass);
    const combiners::CombinerProgram& program = plan.program(pass);
    if (kind == PassKind::AlbedoModulate) {
      draw_albedo_pass(mesh, program);
      return;
    }
    const Material& mat = s.materials[static_cast<size_t>(mesh.material)];
    const size_t l = static_cast<size_t>(pass);
    const auto& buf = buffers_[object];
    combiners::ProgramInputs in;
    in.textures["white"] = {GL_TEXTURE_2D, white_};
    bool secondary = false, texcoords = false;
    if (uses_cube(kind)) {
      const CubeLobe& c = cubes_[static_cast<size_t>(mesh.material)][l];
      in.textures["lobe_cube"] = {GL_TEXTURE_CUBE_MAP, c.texture};
      in.constants["lobe_color"] = glm::dvec4(c.lobe_color, 1);
      gl::stream_array_buffer(buf[0], vt.thickness);
    } else if (kind == PassKind::DiffuseOnly) {
      gl::stream_array_buffer(buf[0], vt.diffuse);
    } else {
      const Light& light = s.lights[l];
      const size_t mi = static_cast<size_t>(mesh.material);
      if (kind == PassKind::LobeVertexMap) {
        in.textures["power_lut"] = {GL_TEXTURE_1D, map_tables_[mi][l]};
        in.textures["thickness_map"] = {GL_TEXTURE_2D, maps_[mi]->id()};
        in.constants["term_gain"] = glm::dvec4(map_term_gain(mat, light), 1);
      } else {
        in.textures["power_lut"] = {GL_TEXTURE_1D, table_textures_[mi]};
        in.constants["lobe_color"] =
            glm::dvec4(lobe_constant(mat, light) / fold_factors(s, mat)[l], 1);
      }
      gl::stream_array_buffer(buf[0], vt.primary[l]);
      gl::stream_array_buffer(buf[2], vt.secondary[l]);
      secondary = true;
      if (program.stages[0].texcoord == combiners::TexCoord::Array) {
        gl::stream_array_buffer(buf[1], vt.texcoord[l]);
        texcoords = true;
      }
    }
    combiners::apply(program, in);
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_TEXTURE);
    if (kind == PassKind::LobeTexgen) {
      const glm::mat4 m =
          texgen_matrix(s, mat, s.lights[l], tables_[static_cast<size_t>(mesh.material)]);
      glLoadMatrixf(glm::value_ptr(m));
    } else {
      glLoadIdentity();
    }
    glMatrixMode(GL_MODELVIEW);

    ctx_.geometry.bind(mesh);
    // Our colours replace the mesh's: thickness is already folded into them.
    glEnableClientState(GL_COLOR_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, buf[0]);
    glColorPointer(4, GL_FLOAT, 0, nullptr);
    if (secondary) {
      glEnableClientState(GL_SECONDARY_COLOR_ARRAY);
      glBindBuffer(GL_ARRAY_BUFFER, buf[2]);
      glSecondaryColorPointer(3, GL_FLOAT, 0, nullptr);
    }
    glClientActiveTexture(GL_TEXTURE0);
    if (texcoords) {
      glEnableClientState(GL_TEXTURE_COORD_ARRAY);
      glBindBuffer(GL_ARRAY_BUFFER, buf[1]);
      glTexCoordPointer(1, GL_FLOAT, 0, nullptr);
    }
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    glDisableClientState(GL_SECONDARY_COLOR_ARRAY);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    ctx_.geometry.unbind();
  }

  // The framebuffer times the albedo map where `mesh` is visible (combiners/albedo_modulate.comb):
  // a pass after the light passes (pass >= 1, so the additive passes' depth EQUAL is on).
  void draw_albedo_pass(const gl::GpuMesh& mesh, const combiners::CombinerProgram& program) {
    combiners::ProgramInputs in;
    in.textures["albedo_map"] = {GL_TEXTURE_2D,
                                 albedo_maps_[static_cast<size_t>(mesh.material)]->id()};
    combiners::apply(program, in);
    glActiveTexture(GL_TEXTURE0);
    glMatrixMode(GL_TEXTURE);
    glLoadIdentity();
    glMatrixMode(GL_MODELVIEW);
    glBlendFunc(GL_DST_COLOR, GL_ZERO);
    ctx_.geometry.bind(mesh);
    glDisableClientState(GL_COLOR_ARRAY);
    glColor4f(1, 1, 1, 1);
    // The UVs (uploaded as set kUvTexCoordSet) on unit 0's set, which this pass's stage reads.
    glClientActiveTexture(GL_TEXTURE0);
    glEnableClientState(GL_TEXTURE_COORD_ARRAY);
    glBindBuffer(GL_ARRAY_BUFFER, mesh.uvs);
    glTexCoordPointer(2, GL_FLOAT, 0, nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glDrawElements(GL_TRIANGLES, mesh.index_count, GL_UNSIGNED_INT, nullptr);
    glDisableClientState(GL_TEXTURE_COORD_ARRAY);
    ctx_.geometry.unbind();
    glBlendFunc(GL_ONE, GL_ONE);  // the additive passes' blend, for the passes still to come
  }

  // The lobe table object `i`'s material samples; null for a material without translucency.
  const LobeTable* table_of(size_t i) const {
    const int m = ctx_.scene.objects[i].material;
    return ctx_.scene.materials[static_cast<size_t>(m)].translucency
               ? &tables_[static_cast<size_t>(m)]
               : nullptr;
  }

  PathContext ctx_;
  FirstFrameFragments fragments_;  // the warning of an empty frame
  CombinersVariant variant_;
  std::vector<CombinerMaterialPlan> plans_;
  std::vector<LobeTable> tables_;  // [material]: t^p or its ramp
  std::vector<GLuint> table_textures_;
  std::vector<std::unique_ptr<gl::MapTexture>> maps_;         // [material], thickness-map materials
  std::vector<std::unique_ptr<gl::MapTexture>> albedo_maps_;  // [material], albedo-map materials
  std::vector<std::vector<GLuint>> map_tables_;               // [material][light], their tables
  std::vector<std::vector<CubeLobe>> cubes_;    // [material][light], lobe=cube passes only
  std::vector<std::array<GLuint, 3>> buffers_;  // per object: primary, texcoord, secondary
  GLuint white_ = 0;
  double cpu_seconds_ = 0, cube_seconds_ = 0;
  int passes_drawn_ = 0;
};

const std::vector<ListedVariant<CombinersVariant>>& combiners_variants() {
  static const std::vector<ListedVariant<CombinersVariant>> listed = {
      {{"t=vertex",
        "t, attenuation, diffuse and thickness per vertex on the CPU; lobe from "
        "an 8-bit LUT per pixel (error grows with triangle size)"},
       CombinersVariant::TVertex},
      {{"t=texgen",
        "t by texgen NORMAL_MAP and the texture matrix (directional lights, "
        "orthographic camera; else as t=vertex)",
        VariantRun::Story},
       CombinersVariant::TTexgen},
      {{"lobe=cube",
        "per pixel: a cube map by the normal holds each directional light's "
        "whole term (exact view only for an orthographic camera); point "
        "lights as t=vertex",
        VariantRun::Story},
       CombinersVariant::LobeCube}};
  return listed;
}

class CombinersInfo final : public ListedPathInfo<CombinersVariant> {
 public:
  CombinersInfo()
      : ListedPathInfo("combiners",
                       "GL 1.3 texture combiners, no shaders: power LUT at a per-vertex t, "
                       "vertex-colour thickness and diffuse, one additive pass per light",
                       combiners_variants()) {
    for (const CombinerBudgetProfile& p : combiner_budget_profiles())
      budget_profiles.push_back(p.name);
    // A hand-written .comb file (combiners/README.md) as one pass.
    program_extensions = {".comb"};
  }
  std::unique_ptr<Path> build(const PathContext& ctx,
                              const CombinersVariant& variant) const override {
    return std::make_unique<CombinersPath>(ctx, variant);
  }
  // Stages, texture units, passes and constant colours against GL 1.3-class hardware.
  budget::Report budget(const Scene& scene, const std::string& variant,
                        const std::string& profile) const override {
    return combiner_budget(scene, profile, variant);
  }
  budget::Report budget_file(const std::string& file, const std::string& profile) const override {
    return combiner_budget_file(file, profile);
  }
};

}  // namespace

CombinersVariant parse_combiners_variant(const std::string& name) {
  return name.empty() ? combiners_variants().front().value
                      : find_listed("combiners", combiners_variants(), name);
}

const PathInfo& combiners_path_info() {
  static const CombinersInfo info;
  return info;
}

}  // namespace lt
