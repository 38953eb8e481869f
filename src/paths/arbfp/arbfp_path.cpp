#include "paths/arbfp/arbfp_path.h"

#include "core/error.h"
#include "gl/map_texture.h"
#include "paths/arbfp/arb_budget.h"
#include "paths/arbfp/arb_file_budget.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_ir_counter.h"
#include "paths/arbfp/arb_program.h"
#include "paths/arbfp/arb_thickness_map.h"
#include "paths/common/frame.h"

namespace lt {

namespace {

// One material's programs and, for the LUT variants, its power texture.
struct MaterialState {
  arbfp::ArbPrograms source;
  std::unique_ptr<arbfp::ArbProgram> vertex, fragment;
  GLuint lut_texture = 0;
  std::unique_ptr<gl::MapTexture> thickness_map;  // on texture unit kThicknessMapUnit
};

GLuint upload_lut(const model::PowerLut& lut) {
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_1D, tex);
  // Linear filtering between texel centres (texel-centre addressing, power_lut.h); clamp to edge
  // so t = 0 and t = 1 return exactly the end texels.
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_1D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
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

void bind_thickness_map(const gl::MapTexture* map) {
  glActiveTexture(GL_TEXTURE0 + arbfp::kThicknessMapUnit);
  glBindTexture(GL_TEXTURE_2D, map ? map->id() : 0);
  glActiveTexture(GL_TEXTURE0);
}

class ArbfpPath final : public Path {
 public:
  ArbfpPath(const PathContext& ctx, const std::string& variant)
      : ctx_(ctx), variant_(arbfp::parse_variant(variant)) {
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
      st->source = arbfp::generate_arb(ctx.scene, mat, variant_);
      st->vertex = std::make_unique<arbfp::ArbProgram>(GL_VERTEX_PROGRAM_ARB, st->source.vertex,
                                                       "arbfp:" + mat.name + " vertex");
      st->fragment = std::make_unique<arbfp::ArbProgram>(
          GL_FRAGMENT_PROGRAM_ARB, st->source.fragment, "arbfp:" + mat.name + " fragment");
      if (st->source.lut) st->lut_texture = upload_lut(*st->source.lut);
      if (mat.translucency && mat.translucency->thickness_map)
        st->thickness_map =
            std::make_unique<gl::MapTexture>(ctx.gl, *mat.translucency->thickness_map);
      materials_[m.material] = std::move(st);
    }
    gl::check_error("building arbfp programs");
  }

  ~ArbfpPath() override {
    for (const auto& m : materials_) {
      if (m && m->lut_texture) glDeleteTextures(1, &m->lut_texture);
    }
  }

  void frame() override {
    begin_frame(ctx_);
    glEnable(GL_VERTEX_PROGRAM_ARB);
    glEnable(GL_FRAGMENT_PROGRAM_ARB);
    glActiveTexture(GL_TEXTURE0);
    for (const gl::GpuMesh& m : ctx_.geometry.meshes()) {
      const MaterialState& st = *materials_[m.material];
      st.vertex->bind();
      st.fragment->bind();
      glBindTexture(GL_TEXTURE_1D, st.lut_texture);
      bind_thickness_map(st.thickness_map.get());
      ctx_.geometry.draw(m);
    }
    bind_thickness_map(nullptr);
    glBindTexture(GL_TEXTURE_1D, 0);
    glDisable(GL_FRAGMENT_PROGRAM_ARB);
    glDisable(GL_VERTEX_PROGRAM_ARB);
  }

  Image result() override { return read_framebuffer(ctx_.gl); }

  // The largest program of the scene: a budget is met or missed by its worst program.
  std::string cost() const override {
    budget::ProgramCounts frag, vert;
    for (const auto& m : materials_) {
      if (!m) continue;
      const budget::ProgramCounts f = arbfp::ir::count(m->source.fragment_program);
      const budget::ProgramCounts v = arbfp::ir::count(m->source.vertex_program);
      if (f.instructions() > frag.instructions()) frag = f;
      if (v.instructions() > vert.instructions()) vert = v;
    }
    return "fragment " + std::to_string(frag.alu) + " ALU + " + std::to_string(frag.tex) +
           " TEX, vertex " + std::to_string(vert.alu) + " ALU";
  }

  std::vector<BuiltStage> stages() const override {
    std::vector<BuiltStage> out;
    for (size_t i = 0; i < materials_.size(); ++i) {
      if (!materials_[i]) continue;
      const MaterialState& st = *materials_[i];
      const std::string name = "material " + ctx_.scene.materials[i].name;
      out.push_back({name + ": vertex program", "arb-vertex", st.source.vertex});
      out.push_back({name + ": fragment program", "arb-fragment", st.source.fragment});
      if (st.source.lut) {
        out.push_back({name + ": power LUT, 1D, " + std::to_string(st.source.lut->size) +
                           " texels " + model::to_string(st.source.lut->format),
                       "texture", ""});
      }
      if (st.thickness_map) {
        out.push_back(
            {name + ": thickness map, one TEX from texture[1]: " + st.thickness_map->description(),
             "texture", ""});
      }
      for (const std::string& n : st.source.notes) out.push_back({name + ": " + n, "note", ""});
    }
    return out;
  }

 private:
  PathContext ctx_;
  arbfp::PowVariant variant_;
  std::vector<std::unique_ptr<MaterialState>> materials_;
};

}  // namespace

PathInfo arbfp_path_info() {
  PathInfo info{
      "arbfp",
      "per-pixel ARB vertex/fragment programs (SM2), generated per material; pow variants",
      {
          // The default: the cheapest variant (fewest ALU + TEX on every demo scene, no texture)
          // whose max error is <= 2 LSB on every demo scene (bench, see the closing note).
          {"pow=mul", "t^p by repeated squaring (integer p; non-integer p uses exact POW)"},
          // The cheapest fragment program (t and the lobe in the vertex program), not the default:
          // its error is the lobe's Gouraud interpolation, which grows with triangle size.
          {"pow=mul:vertex",
           "t^p by repeated squaring per vertex, lobe interpolated: fewest fragment ALU, error "
           "grows with triangle size"},
          {"pow=exact", "POW with 0^0 guarded by CMP: float error only"},
          {"pow=lut:256:u8",
           "256-texel 8-bit LUT: 1 MAD + 1 TEX, u8 rounding (0.5/255 of the lobe)"},
          {"pow=lut:64:u8", "64-texel 8-bit LUT: interpolation error grows with p"},
          {"pow=lut:16:u8", "16-texel 8-bit LUT: coarse, large error for p > 2"},
          {"pow=lut:256:f16", "256-texel half-float LUT"},
          {"pow=lut:64:f16", "64-texel half-float LUT"},
          {"pow=lut:32:f32", "32-texel float LUT: interpolation error only"},
          {"pow=sg", "exp2(n'(t-1)), n' = 1.4427p + 1.4427: 2 ALU, a close but different curve"},
          {"pow=sg-fitted", "exp2(n'(t-1)) with n' fitted per material to the max error"},
          {"pow=sg-simplified", "exp2(p(t-1)): a different curve, ~35-40 LSB off (model.md)"},
      },
      [](const PathContext& ctx, const std::string& variant) -> std::unique_ptr<Path> {
        return std::make_unique<ArbfpPath>(ctx, variant);
      }};
  // The variant grammar: any LUT width and format the generator builds, not just the rows the
  // bench runs ("pow=lut:128:f16").
  info.parse_variant = [](const std::string& v) { return arbfp::parse_variant(v).name(); };
  // The per-vertex lobe packs four lights per texcoord: a scene with more lights cannot take it
  // (bench skips it and says so, render refuses it with this reason).
  info.refusal = [](const Scene& scene, const std::string& v) -> std::string {
    // An rgb ramp per light does not fit the lobe's four-lights-a-register lanes (not built yet).
    if (scene_needs(scene).any_ramp) return "no lobe ramps on arbfp yet";
    if (!arbfp::parse_variant(v).per_vertex || scene.lights.size() <= arbfp::kMaxVertexLobeLights)
      return "";
    for (const Material& m : scene.materials) {
      if (m.translucency && m.translucency->power != 0) {
        return "the per-vertex lobe takes at most " + std::to_string(arbfp::kMaxVertexLobeLights) +
               " lights (four per texcoord, texcoord[3..7]); the scene has " +
               std::to_string(scene.lights.size());
      }
    }
    return "";
  };
  // Instructions, temporaries, parameters and indirections against ps_2_0 and friends.
  info.budget = [](const Scene& scene, const BudgetRequest& rq) {
    const budget::BudgetReport r =
        budget::run_budget(scene, "arbfp", rq.variant, rq.profile.empty() ? "ps_2_0" : rq.profile);
    *rq.out << (rq.json ? budget::to_json(r).dump(2) + "\n" : budget::format_table(r));
    *rq.first_overrun = r.first_overrun();
    return r.fits();
  };
  // Hand-written ARB_vertex_program / ARB_fragment_program text, checked by our counter and by
  // Mesa (arb_file_budget.h).
  info.program_extensions = {".fp", ".vp", ".arb"};
  info.program_headers = {"!!ARBfp1.0", "!!ARBvp1.0"};
  info.budget_file = [](const std::string& file, const BudgetRequest& rq) {
    const arbfp::FileBudget b = arbfp::budget_arb_file(file, rq.profile);
    *rq.out << (rq.json ? arbfp::to_json(b).dump(2) + "\n" : arbfp::to_text(b));
    *rq.first_overrun = b.first_overrun();
    return b.fits();
  };
  return info;
}

}  // namespace lt
