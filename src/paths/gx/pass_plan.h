// What the gx generator decided, per material and pass, before a line of C is written: the typed
// plan that three steps share (generator.h):
//   plan_scene    (pass_planner.cpp)  the choices: scales, flags, what the scene needs
//   emit_programs (plan_emitter.cpp)  the plan as libogc calls, the C a porter reads
//   describe_pass (plan_notes.cpp)    the plan as the human note
// Every GX constant is a GxConst of its group, checked against libogc's names when ltrender is
// compiled (program/gx_names.h); every colour is the 8-bit GXColor the call passes and every
// number the float it passes, so what the plan says is exactly what the program sets
// (tests/gx_plan_test.cpp runs the emitted C through the interpreter and compares).
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "gx/gx_types.h"
#include "gx/program/gx_names.h"
#include "gx/vertex_storage.h"

namespace lt::gx {

// The vertex format's attributes: position and normal (XYZ) always, then the baked thickness colour
// (GX_VA_CLR0), the CPU's t (GX_VA_TEX0, GX_TEX_S) and the mesh's UV (GX_VA_TEX<uv_attribute>,
// GX_TEX_ST).
// How the format declares them (VertexDeclarations): the variant's vertex storage (:vtx= :nrm=
// :clr= :uv=) with each /auto fraction resolved once for the scene (storage_declarations,
// scene_vertices.h), and, where :draw= sends indices, GX_INDEX8 or GX_INDEX16 per array (the
// index the FIFO log gives it), in the variant's vertex format (:vat=N: GX_VTXFMTN). The default
// variant's: GX_VTXFMT0, GX_F32, GX_RGBA8, GX_DIRECT.
struct VertexDeclarations {
  VertexStorage storage;  // no auto_frac left
  int format = 0;         // GX_VTXFMTn
  bool indexed = false;
  std::array<bool, kVertexArrays> index16{};  // by array number (vertex_format.h)
  bool operator==(const VertexDeclarations&) const = default;
};

struct VertexFormatPlan {
  bool colour = false;
  bool t = false;
  bool uv = false;
  VertexDeclarations declared;
  // The UV rides in the texture coordinate after t: the XF is told only how many texture
  // coordinates arrive (program_check.h), so they are declared without a gap.
  int uv_attribute() const { return t ? 1 : 0; }
};

// A light object, loaded into one hardware light. Either a distance-attenuated light (spot off:
// a = (1, 0, 0); k = (kc, kl, kq) / gain, so the XF computes gain x att x colour) or, for
// lobe=xf-spec, the specular light whose angular attenuation is the fitted lobe.
struct LightObjectPlan {
  enum class Kind { Distance, SpecularFit };
  Kind kind = Kind::Distance;
  std::string name;  // the C variable
  GxConst<NameGroup::Light> slot{"GX_LIGHT0"};
  glm::vec3 position{0};            // eye space
  Color8 color{};                   // normalised to 255 at its largest component
  glm::vec3 direction_arg{0};       // what GX_InitLightDir is passed (it stores the negation)
  std::array<float, 3> k{1, 0, 0};  // distance: (kc, kl, kq) / gain; fit: the denominator
  std::array<float, 3> a{1, 0, 0};  // fit: the numerator x the channel's magnitude
  double gain = 1;                  // distance: the magnitude moved into k
};

// Which hardware lights a channel sums: printed as GX_LIGHTn when the plan names one light,
// as the bit mask otherwise, GX_LIGHTNULL when empty.
struct LightMask {
  int bits = 0;
  bool named = false;
};

// GX_SetChanCtrl and the channel's ambient and material registers (unset: not written).
struct ChannelPlan {
  GxConst<NameGroup::Channel> channel{"GX_COLOR0A0"};
  GxConst<NameGroup::Bool> enable{"GX_ENABLE"};
  GxConst<NameGroup::ColorSource> ambient_source{"GX_SRC_REG"};
  GxConst<NameGroup::ColorSource> material_source{"GX_SRC_REG"};
  LightMask lights;
  GxConst<NameGroup::DiffuseFn> diffuse_fn{"GX_DF_CLAMP"};
  GxConst<NameGroup::AttnFn> attenuation_fn{"GX_AF_SPOT"};
  std::optional<Color8> ambient, material;
  std::string what, material_what;  // the comments before the control and the material colour
};

// A texture object and the map it is loaded into: GX_InitTexObj(array, size, format, wrap,
// no mipmaps), linear filtering.
struct TexturePlan {
  enum class Role { Lut, ThicknessMap, AlbedoMap };
  Role role = Role::Lut;
  std::string object, array;  // the GXTexObj and the u8 array
  int width = 0, height = 0;
  GxConst<NameGroup::TexFormat> format{"GX_TF_I8"};
  GxConst<NameGroup::TexWrap> wrap_s{"GX_CLAMP"}, wrap_t{"GX_CLAMP"};
  GxConst<NameGroup::TexMap> map{"GX_TEXMAP0"};
  size_t bytes = 0;
  std::string what;
  // A colour-indexed texture's palette: GX_InitTlutObj(&object, array, format, entries) and
  // GX_LoadTlut(&object, name) before GX_InitTexObjCI(..., name) [OGC gx.c L3301, L3421, L3648].
  struct Tlut {
    std::string object, array;
    GxConst<NameGroup::TlutFormat> format{"GX_TL_RGB565"};
    int entries = 0;
    GxConst<NameGroup::TlutName> name{"GX_TLUT0"};
  };
  std::optional<Tlut> tlut;
  // A mipmapped texture (:mip=, gx_variant.h): `levels` levels in the array, GX_InitTexObj with
  // mipmap GX_TRUE then GX_InitTexObjLOD(min_filter, GX_LINEAR, 0, max_lod, bias, GX_FALSE,
  // GX_TRUE, GX_ANISO_1) [OGC gx.c L3310].
  struct Mip {
    int levels = 1;
    GxConst<NameGroup::TexFilter> min_filter{"GX_LIN_MIP_LIN"};
    float max_lod = 0, bias = 0;
    bool edge_lod = true;  // GX_InitTexObjLOD's edgelod (false: diagonal LOD, :mip-lod=diagonal)
  };
  std::optional<Mip> mip;
};

// A texture matrix loaded before the texgens (GX_LoadTexMtxImm, 2x4): 12 floats row by row.
struct TexMatrixPlan {
  std::string name;
  GxConst<NameGroup::TexMtx> slot{"GX_TEXMTX0"};
  std::array<float, 12> values{};
  std::string what;
};

// GX_SetTexCoordGen and the texture its coordinates fetch.
struct TexGenPlan {
  GxConst<NameGroup::TexCoord> coord{"GX_TEXCOORD0"};
  GxConst<NameGroup::TexGenType> type{"GX_TG_MTX2x4"};
  GxConst<NameGroup::TexGenSource> source{"GX_TG_TEX0"};
  GxConst<NameGroup::TexMtx> matrix{"GX_IDENTITY"};
  std::optional<TexMatrixPlan> matrix_values;  // loaded by this pass
  std::optional<TexturePlan> texture;
  std::string what;
};

// One combiner of a stage: out = dest <- clamp((d + lerp(a, b, c) + bias) x scale).
template <NameGroup Arg>
struct CombinerPlan {
  std::array<GxConst<Arg>, 4> in;
  GxConst<NameGroup::TevOp> op{"GX_TEV_ADD"};
  GxConst<NameGroup::TevBias> bias{"GX_TB_ZERO"};
  GxConst<NameGroup::TevScale> scale{"GX_CS_SCALE_1"};
  GxConst<NameGroup::Bool> clamp{"GX_TRUE"};
  GxConst<NameGroup::TevReg> dest{"GX_TEVPREV"};
};

struct TevStagePlan {
  GxConst<NameGroup::TevStage> stage{"GX_TEVSTAGE0"};
  GxConst<NameGroup::TexCoord> texcoord{"GX_TEXCOORDNULL"};
  GxConst<NameGroup::TexMap> texmap{"GX_TEXMAP_NULL"};
  GxConst<NameGroup::Channel> channel{"GX_COLORNULL"};
  CombinerPlan<NameGroup::ColorArg> color{{"GX_CC_ZERO", "GX_CC_ZERO", "GX_CC_ZERO", "GX_CC_ZERO"}};
  // An alpha of 255 (KASEL 1) everywhere: the EFB keeps no alpha (RGB8_Z24).
  CombinerPlan<NameGroup::AlphaArg> alpha{
      {"GX_CA_ZERO", "GX_CA_ZERO", "GX_CA_ZERO", "GX_CA_KONST"}};
  GxConst<NameGroup::KAlphaSel> konst_alpha{"GX_TEV_KASEL_1"};
  // The konst colour the colour combiner's KONST reads (unset: not written, GX_Init's 1).
  std::optional<GxConst<NameGroup::KColorSel>> konst_color;
  // Which of the pass's data-dependent scales the stage's output scale is: the translucency's
  // or the diffuse's (PassFigures), which a module's setup chooses again each frame
  // (module/module_exporter.cpp), or none (a fixed x1).
  enum class FrameScale { None, Translucency, Diffuse };
  FrameScale frame_scale = FrameScale::None;
  std::string what;  // "Stage 0: out = COLOR0 x 2"
};

struct TevRegisterPlan {
  GxConst<NameGroup::TevReg> reg{"GX_TEVREG0"};
  Color8 value{};
  std::string what;
};

// Pass 0 replaces what the EFB holds; later passes add onto it (ONE, ONE), the depth of pass 0
// tested but not rewritten; both sides drawn.
struct PixelEnginePlan {
  GxConst<NameGroup::BlendMode> blend{"GX_BM_NONE"};
  GxConst<NameGroup::BlendFactor> src{"GX_BL_ONE"}, dst{"GX_BL_ZERO"};
  GxConst<NameGroup::LogicOp> logic{"GX_LO_CLEAR"};
  GxConst<NameGroup::Bool> z_enable{"GX_TRUE"};
  GxConst<NameGroup::Compare> z_func{"GX_LEQUAL"};
  GxConst<NameGroup::Bool> z_update{"GX_TRUE"};
  GxConst<NameGroup::Compare> alpha_comp0{"GX_ALWAYS"}, alpha_comp1{"GX_ALWAYS"};
  GxConst<NameGroup::AlphaOp> alpha_op{"GX_AOP_AND"};
  int alpha_ref0 = 0, alpha_ref1 = 0;
  GxConst<NameGroup::CullMode> cull{"GX_CULL_NONE"};
  std::string what;
};

// The figures the note reports: what the planner chose and what it could not hold.
struct PassFigures {
  bool diffuse_only = false;
  size_t light = 0;  // the pass's light (a diffuse-only pass: its first)
  int translucency_scale = 1, diffuse_scale = 1;
  bool translucency_saturates = false, diffuse_saturates = false;
  std::optional<double> fit_error;  // lobe=xf-spec: the fit's max error, in units of (a+s)
  // The thickness the material register's 255 stands for (the constant's largest component, a
  // map's largest texel, 1 for vertex colours): the module's setup scales by it each frame.
  double thickness_scale = 1;
};

// A konst colour register (GX_SetTevKColor).
struct KonstColorPlan {
  GxConst<NameGroup::KColor> reg{"GX_KCOLOR0"};
  Color8 value{};
  std::string what;
};

struct PassPlan {
  VertexFormatPlan vertex;
  std::vector<LightObjectPlan> lights;
  std::string channels_what;  // the comment on GX_SetNumChans
  std::vector<ChannelPlan> channels;
  std::vector<TexGenPlan> texgens;
  std::optional<TevRegisterPlan> tev_register;
  std::optional<KonstColorPlan> konst_color;
  std::vector<TevStagePlan> stages;
  PixelEnginePlan pixel;
  PassFigures figures;
};

// A u8 array at the top of the file (a LUT or a thickness map), with its comment.
struct ArrayPlan {
  std::string name;
  std::vector<u8> bytes;
  std::string what;
};

struct MaterialPlan {
  int material = 0;    // index in scene.materials
  std::string name;    // as the scene names it
  std::string c_name;  // the unique C identifier of that name (pass_programs.h)
  std::vector<ArrayPlan> arrays;
  std::vector<PassPlan> passes;
};

struct ScenePlan {
  std::vector<MaterialPlan> materials;  // the materials some object uses, in scene order
};

// The light whose t pass `pass` of `m` sends (the pass must send t): the module's C fills t for
// this light. The emulator and the FIFO log, which also draw users' programs that name no light,
// take a pass's number as its light's (VertexStream::t_per_light indexed by pass:
// frame_recording.cpp, scene_vertices.cpp, vertex_stage.cpp). The planner makes the two one
// number by giving a material that sends t one pass a light, in the scene's order; a plan where
// they differ is a bug, stopped here rather than exported.
size_t sent_t_light(const MaterialPlan& m, size_t pass);

// A number in a comment or note, as an ostream prints a double ("0.25", "1e+18").
std::string note_number(double v);

}  // namespace lt::gx
