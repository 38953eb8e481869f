#include "paths/arbfp/arbfp_path.h"

#include <algorithm>

#include "arb/arb_ir_counter.h"
#include "arb/arb_program.h"
#include "budget/shader_model_file_budget.h"
#include "core/error.h"
#include "core/fs.h"
#include "gl/map_texture.h"
#include "paths/arbfp/arb_albedo_map.h"
#include "paths/arbfp/arb_budget.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_lobe.h"
#include "paths/arbfp/arb_passes.h"
#include "paths/arbfp/arb_thickness_map.h"
#include "paths/common/first_frame_fragments.h"
#include "paths/common/frame.h"

namespace lt {

namespace {

// One pass of a material: its programs and, for the LUT variants, its power texture.
struct PassState {
  arbfp::Pass plan;
  std::unique_ptr<arbfp::ArbProgram> vertex, fragment;
  GLuint lut_texture = 0;
};

// One material's passes (one unless --profile split its lights, arb_passes.h).
struct MaterialState {
  std::vector<PassState> passes;
  std::unique_ptr<gl::MapTexture> thickness_map;  // on texture unit kThicknessMapUnit
  std::unique_ptr<gl::MapTexture> albedo_map;     // on texture unit kAlbedoMapUnit
  // A lobe ramp on kLobeTableUnit (2D): every pass's program reads it instead of a power LUT.
  std::unique_ptr<gl::MapTexture> ramp;
};

GLuint upload_lut(const model::PowerLut& lut) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_1D, tex);
  // Linear filtering between texel centres (texel-centre addressing, power_lut.h); clamp to edge
  // so t = 0 and t = 1 return exactly the end texels.
  gl::set_linear_clamp_to_edge(GL_TEXTURE_1D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (lut.format == model::LutFormat::U8) {
    // The texels are already multiples of 1/255: upload the bytes so GL does no rounding of its
    // own.
    std::vector<unsigned char> bytes(lut.texels.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
      bytes[i] = static_cast<unsigned char>(std::lround(lut.texels[i] * 255.0));
    }
    glTexImage1D(GL_TEXTURE_1D, 0, GL_R8, lut.size, 0, GL_RED, GL_UNSIGNED_BYTE, bytes.data());
  } else {
    // f16 texels are already representable halves, so the float->half conversion is exact.
    const GLint internal = lut.format == model::LutFormat::F16 ? GL_R16F : GL_R32F;
    glTexImage1D(GL_TEXTURE_1D, 0, internal, lut.size, 0, GL_RED, GL_FLOAT, lut.texels.data());
  }
  glBindTexture(GL_TEXTURE_1D, 0);
  return tex;
}

// The material's 2D textures: the thickness map (texture[1]), the lobe ramp (texture[0], whose
// 1D target holds the power LUT of pow=lut: a program reads one of the two) and the albedo map
// (texture[2]).
void bind_material_textures(const MaterialState* st) {
  const std::pair<int, const gl::MapTexture*> units[] = {
      {arbfp::kThicknessMapUnit, st ? st->thickness_map.get() : nullptr},
      {arbfp::kLobeTableUnit, st ? st->ramp.get() : nullptr},
      {arbfp::kAlbedoMapUnit, st ? st->albedo_map.get() : nullptr}};
  for (const auto& [unit, texture] : units) {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, texture ? texture->id() : 0);
  }
  glActiveTexture(GL_TEXTURE0);
}

class ArbfpPath final : public Path {
 public:
  ArbfpPath(const PathContext& ctx, const arbfp::PowVariant& variant)
      : ctx_(ctx), fragments_("arbfp", ctx.geometry), variant_(variant) {
    ctx.gl.require_extension("GL_ARB_vertex_program", "the arbfp path");
    ctx.gl.require_extension("GL_ARB_fragment_program", "the arbfp path");
    // The generator writes light positions relative to the eye; the geometry must agree.
    LT_CHECK(ctx.geometry.origin() == ctx.scene.camera.eye,
             "camera-relative origin is not the eye");
    materials_.resize(ctx.scene.materials.size());
    for (const gl::GpuMesh& m : ctx.geometry.meshes()) {
      if (materials_[m.material]) continue;
      const Material& mat = ctx.scene.materials[m.material];
      auto st = std::make_unique<MaterialState>();
      arbfp::PassPlan plan = arbfp::plan_passes(ctx.scene, mat, variant_, ctx.options.profile);
      for (size_t i = 0; i < plan.passes.size(); ++i) {
        PassState ps;
        ps.plan = std::move(plan.passes[i]);
        const std::string name =
            "arbfp:" + mat.name + (plan.passes.size() > 1 ? " pass " + std::to_string(i + 1) : "");
        ps.vertex = std::make_unique<arbfp::ArbProgram>(GL_VERTEX_PROGRAM_ARB,
                                                        ps.plan.programs.vertex, name + " vertex");
        ps.fragment = std::make_unique<arbfp::ArbProgram>(
            GL_FRAGMENT_PROGRAM_ARB, ps.plan.programs.fragment, name + " fragment");
        if (ps.plan.programs.lut) ps.lut_texture = upload_lut(*ps.plan.programs.lut);
        st->passes.push_back(std::move(ps));
      }
      passes_ = std::max(passes_, st->passes.size());
      // A float map as half: what the float-filtering ps_2_x parts hold (gl/map_texture.h).
      if (mat.translucency && mat.translucency->thickness_map)
        st->thickness_map = std::make_unique<gl::MapTexture>(
            ctx.gl, *mat.translucency->thickness_map, gl::MapTexelClass::Fp16);
      // The glsl path's upload of the same albedo map: decoded linear colour as half.
      if (mat.albedo_map)
        st->albedo_map =
            std::make_unique<gl::MapTexture>(ctx.gl, *mat.albedo_map, gl::MapTexelClass::Fp16);
      // The glsl path's upload of the same ramp (gl/map_texture.h): both sample one texture.
      if (mat.translucency && mat.translucency->ramp)
        st->ramp = std::make_unique<gl::MapTexture>(ctx.gl, *mat.translucency->ramp,
                                                    gl::MapTexelClass::Fp16);
      materials_[m.material] = std::move(st);
    }
    gl::check_error("building arbfp programs");
  }

  ~ArbfpPath() override {
    for (const auto& m : materials_) {
      if (!m) continue;
      for (const PassState& ps : m->passes) {
        if (ps.lut_texture) glDeleteTextures(1, &ps.lut_texture);
      }
    }
  }

  // Pass 0 of every mesh (depth LESS, depth writes), then pass k of every mesh that has one:
  // depth EQUAL against pass 0's depth (ARB_position_invariant makes every pass's depth the
  // same), ONE + ONE blending, no depth writes. The 8-bit framebuffer clamps and rounds each
  // pass's sum (docs/arbfp.md, "Passes").
  void frame() override {
    begin_frame(ctx_);
    fragments_.begin();
    glEnable(GL_VERTEX_PROGRAM_ARB);
    glEnable(GL_FRAGMENT_PROGRAM_ARB);
    glActiveTexture(GL_TEXTURE0);
    for (size_t k = 0; k < passes_; ++k) {
      if (k == 1) begin_additive_passes();
      for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
        const MaterialState& st = *materials_[m.material];
        if (k >= st.passes.size()) continue;
        const PassState& ps = st.passes[k];
        ps.vertex->bind();
        ps.fragment->bind();
        glBindTexture(GL_TEXTURE_1D, ps.lut_texture);
        bind_material_textures(&st);
        ctx_.geometry.draw(m);
      }
    }
    if (passes_ > 1) end_additive_passes();
    fragments_.end();
    bind_material_textures(nullptr);
    glBindTexture(GL_TEXTURE_1D, 0);
    glDisable(GL_FRAGMENT_PROGRAM_ARB);
    glDisable(GL_VERTEX_PROGRAM_ARB);
  }

  Image result() override { return read_framebuffer(ctx_.gl); }

  // The largest program of the scene (a budget is met or missed by its worst program), and the
  // passes when --profile split a material.
  std::string cost() const override {
    budget::ProgramCounts frag, vert;
    for (const auto& m : materials_) {
      if (!m) continue;
      for (const PassState& ps : m->passes) {
        const budget::ProgramCounts& f = ps.plan.fragment_counts;
        const budget::ProgramCounts& v = ps.plan.vertex_counts;
        if (f.instructions() > frag.instructions()) frag = f;
        if (v.instructions() > vert.instructions()) vert = v;
      }
    }
    std::string s = "fragment " + std::to_string(frag.alu) + " ALU + " + std::to_string(frag.tex) +
                    " TEX, vertex " + std::to_string(vert.alu) + " ALU";
    if (passes_ > 1) s += ", " + std::to_string(passes_) + " passes (" + ctx_.options.profile + ")";
    return s;
  }

  // Each fragment instruction runs once a covered pixel, each vertex instruction once a vertex,
  // the 4 DP4 that ARB_position_invariant adds included (what vs_2_0 counts as slots); summed
  // over the passes --profile split a material into.
  WorkModel work() const override {
    WorkModel w{"fragment ALU + TEX instruction", "vertex instruction", {}, {}};
    w.by_material.resize(materials_.size());
    for (size_t i = 0; i < materials_.size(); ++i) {
      if (!materials_[i]) continue;
      for (const PassState& ps : materials_[i]->passes) {
        const budget::ProgramCounts& f = ps.plan.fragment_counts;
        const budget::ProgramCounts& v = ps.plan.vertex_counts;
        w.by_material[i].per_pixel += f.instructions();
        w.by_material[i].per_vertex += v.instructions() + (v.position_invariant ? 4 : 0);
      }
    }
    return w;
  }

  std::vector<BuiltStage> stages() const override {
    std::vector<BuiltStage> out;
    for (size_t i = 0; i < materials_.size(); ++i) {
      if (!materials_[i]) continue;
      const MaterialState& st = *materials_[i];
      const std::string material = "material " + ctx_.scene.materials[i].name;
      if (st.passes.size() > 1) {
        out.push_back({material + ": " + std::to_string(st.passes.size()) + " passes to fit " +
                           ctx_.options.profile,
                       "note", ""});
      }
      for (size_t k = 0; k < st.passes.size(); ++k) {
        const PassState& ps = st.passes[k];
        const arbfp::ArbPrograms& src = ps.plan.programs;
        std::string name = material;
        if (st.passes.size() > 1) {
          name += ", pass " + std::to_string(k + 1) + " (" + arbfp::describe(ps.plan) + "; " +
                  std::to_string(ps.plan.fragment_counts.alu) + " ALU, " +
                  std::to_string(ps.plan.fragment_counts.temporaries) + " temps)";
        }
        out.push_back({name + ": vertex program", "arb-vertex", src.vertex});
        out.push_back({name + ": fragment program", "arb-fragment", src.fragment});
        if (src.lut) {
          out.push_back({name + ": power LUT, 1D, " + std::to_string(src.lut->size) + " texels " +
                             model::to_string(src.lut->format),
                         "texture", ""});
        }
        for (const std::string& n : src.notes) out.push_back({name + ": " + n, "note", ""});
      }
      if (st.thickness_map) {
        out.push_back({material + ": thickness map, one TEX from texture[1]: " +
                           st.thickness_map->description(),
                       "texture", ""});
      }
      if (st.albedo_map) {
        out.push_back({material + ": albedo map, one TEX from texture[2] times the albedo: " +
                           st.albedo_map->description(),
                       "texture", ""});
      }
      if (st.ramp) {
        out.push_back({material + ": lobe ramp, one TEX per light from texture[0] (2D, replaces " +
                           "t^p in every variant): " + st.ramp->description(),
                       "texture", ""});
      }
    }
    return out;
  }

 private:
  PathContext ctx_;
  FirstFrameFragments fragments_;  // the warning of an empty frame
  arbfp::PowVariant variant_;
  std::vector<std::unique_ptr<MaterialState>> materials_;
  size_t passes_ = 1;  // the most passes of any material
};

// The variant grammar: any LUT width and format the generator builds, not just the rows the
// bench runs ("pow=lut:128:f16").
class ArbfpInfo final : public TypedPathInfo<arbfp::PowVariant> {
 public:
  ArbfpInfo();
  arbfp::PowVariant parse(const std::string& v) const override { return arbfp::parse_variant(v); }
  std::string name_of(const arbfp::PowVariant& v) const override { return v.name(); }
  std::unique_ptr<Path> build(const PathContext& ctx, const arbfp::PowVariant& v) const override {
    return std::make_unique<ArbfpPath>(ctx, v);
  }
  // The per-vertex lobe (or t) packs four lights per texcoord: a scene with more lights cannot
  // take it (bench skips it and says so, render refuses it with this reason).
  std::string refuse(const Scene& scene, const arbfp::PowVariant& v) const override {
    if (!v.per_vertex || scene.lights.size() <= arbfp::kMaxVertexLobeLights) return "";
    for (const Material& m : scene.materials) {
      if (m.translucency && arbfp::lobe_varies(*m.translucency)) {
        return "the per-vertex lobe takes at most " + std::to_string(arbfp::kMaxVertexLobeLights) +
               " lights (four per texcoord, texcoord[3..7]); the scene has " +
               std::to_string(scene.lights.size());
      }
    }
    return "";
  }
  // Instructions, temporaries, parameters and indirections against ps_2_0 and friends.
  budget::Report budget(const Scene& scene, const std::string& v,
                        const std::string& profile) const override {
    return budget::run_budget(scene, v, profile);
  }
  // Hand-written ARB programs or Direct3D 9 assembly, the same shader model's two languages
  // (budget/shader_model_file_budget.h).
  budget::Report budget_file(const std::string& file, const std::string& profile) const override {
    return budget::budget_shader_model_file(file, profile);
  }
  bool reads_program_text(const std::string& text) const override {
    return budget::is_shader_model_program_text(text);
  }
};

ArbfpInfo::ArbfpInfo() {
  name = "arbfp";
  summary =
      "per-pixel ARB vertex/fragment programs (SM2), generated per material; pow variants (a "
      "lobe-ramp material reads its ramp, one TEX per light, in every variant: no pow to "
      "replace)";
  variants = {
      // The default: the cheapest variant (fewest ALU + TEX on every demo scene, no texture)
      // whose max error is <= 2 LSB on every demo scene (bench, see the closing note).
      {"pow=mul", "t^p by repeated squaring (integer p; non-integer p uses exact POW)"},
      // The Story variants (./run.sh's quick run) are the rows of docs/measurements.md's table:
      // the cheapest fragment program, the 256-texel LUTs, the two spherical Gaussians.
      // The cheapest fragment program (t and the lobe in the vertex program), not the default:
      // its error is the lobe's Gouraud interpolation, which grows with triangle size.
      {"pow=mul:vertex",
       "t^p by repeated squaring per vertex, lobe interpolated: fewest fragment ALU, error "
       "grows with triangle size (a ramp: t per vertex, the ramp per pixel)",
       VariantRun::Story},
      {"pow=exact", "POW with 0^0 guarded by CMP: float error only"},
      {"pow=lut:256:u8", "256-texel 8-bit LUT: 1 MAD + 1 TEX, u8 rounding (0.5/255 of the lobe)",
       VariantRun::Story},
      {"pow=lut:64:u8", "64-texel 8-bit LUT: interpolation error grows with p"},
      {"pow=lut:16:u8", "16-texel 8-bit LUT: coarse, large error for p > 2"},
      {"pow=lut:256:f16", "256-texel half-float LUT", VariantRun::Story},
      {"pow=lut:64:f16", "64-texel half-float LUT"},
      {"pow=lut:32:f32", "32-texel float LUT: interpolation error only"},
      {"pow=sg", "exp2(n'(t-1)), n' = 1.4427p + 1.4427: 2 ALU, a close but different curve",
       VariantRun::Story},
      {"pow=sg-fitted", "exp2(n'(t-1)) with n' fitted per material to the max error"},
      {"pow=sg-simplified", "exp2(p(t-1)): another curve, ~35-40 LSB off (docs/spec/model.md)",
       VariantRun::Story},
  };
  for (const budget::Profile& p : budget::all_profiles()) budget_profiles.push_back(p.name);
  takes_profile = true;
  program_extensions = {".fp", ".vp", ".arb", ".asm", ".vsh", ".psh"};
}

}  // namespace

const PathInfo& arbfp_path_info() {
  static const ArbfpInfo info;
  return info;
}

}  // namespace lt
