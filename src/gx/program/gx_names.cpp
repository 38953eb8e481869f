#include "gx/program/gx_names.h"

#include <unordered_map>

#include "gx/program/gx_name_table.h"

namespace lt::gx {

const GxName* find_gx_name(std::string_view name) {
  static const std::unordered_map<std::string_view, const GxName*> index = [] {
    std::unordered_map<std::string_view, const GxName*> m;
    for (const GxName& n : kGxNames) m.emplace(n.name, &n);
    return m;
  }();
  const auto it = index.find(name);
  return it == index.end() ? nullptr : it->second;
}

std::string describe(NameGroup group) {
  switch (group) {
    case NameGroup::PosMtx:
      return "a position matrix (GX_PNMTX0..9)";
    case NameGroup::CullMode:
      return "a cull mode (GX_CULL_*)";
    case NameGroup::PixelFormat:
      return "an EFB pixel format (GX_PF_*)";
    case NameGroup::ZFormat:
      return "a depth compression (GX_ZC_*)";
    case NameGroup::Number:
      return "a number";
    case NameGroup::Bool:
      return "a boolean (GX_TRUE/GX_FALSE, GX_ENABLE/GX_DISABLE)";
    case NameGroup::Channel:
      return "a colour channel (GX_COLOR0A0, GX_COLOR1A1, ...)";
    case NameGroup::ColorSource:
      return "a colour source (GX_SRC_REG, GX_SRC_VTX)";
    case NameGroup::Light:
      return "a light mask (GX_LIGHT0..7, GX_LIGHTNULL)";
    case NameGroup::DiffuseFn:
      return "a diffuse function (GX_DF_*)";
    case NameGroup::AttnFn:
      return "an attenuation function (GX_AF_*)";
    case NameGroup::SpotFn:
      return "a spot function (GX_SP_*)";
    case NameGroup::DistFn:
      return "a distance function (GX_DA_*)";
    case NameGroup::TexCoord:
      return "a texture coordinate (GX_TEXCOORD0..7, GX_TEXCOORDNULL)";
    case NameGroup::TexMap:
      return "a texture map (GX_TEXMAP0..7, GX_TEXMAP_NULL)";
    case NameGroup::TevStage:
      return "a TEV stage (GX_TEVSTAGE0..15)";
    case NameGroup::ColorArg:
      return "a colour input (GX_CC_*)";
    case NameGroup::AlphaArg:
      return "an alpha input (GX_CA_*)";
    case NameGroup::TevOp:
      return "a TEV operation (GX_TEV_ADD, GX_TEV_SUB, GX_TEV_COMP_*)";
    case NameGroup::TevBias:
      return "a TEV bias (GX_TB_*)";
    case NameGroup::TevScale:
      return "a TEV scale (GX_CS_*)";
    case NameGroup::TevReg:
      return "a TEV register (GX_TEVPREV, GX_TEVREG0..2)";
    case NameGroup::KColor:
      return "a konst colour (GX_KCOLOR0..3)";
    case NameGroup::KColorSel:
      return "a konst colour selector (GX_TEV_KCSEL_*)";
    case NameGroup::KAlphaSel:
      return "a konst alpha selector (GX_TEV_KASEL_*)";
    case NameGroup::TevMode:
      return "a TEV preset (GX_MODULATE, GX_DECAL, GX_BLEND, GX_REPLACE, GX_PASSCLR)";
    case NameGroup::Swap:
      return "a swap table (GX_TEV_SWAP0..3)";
    case NameGroup::ColorComponent:
      return "a colour component (GX_CH_RED, GX_CH_GREEN, GX_CH_BLUE, GX_CH_ALPHA)";
    case NameGroup::TexGenType:
      return "a texgen type (GX_TG_MTX2x4, GX_TG_MTX3x4)";
    case NameGroup::TexGenSource:
      return "a texgen source (GX_TG_POS, GX_TG_NRM, GX_TG_TEX0..7)";
    case NameGroup::TexMtx:
      return "a texture matrix (GX_TEXMTX0..9, GX_IDENTITY)";
    case NameGroup::MtxType:
      return "a matrix type (GX_MTX2x4, GX_MTX3x4)";
    case NameGroup::Compare:
      return "a comparison (GX_NEVER .. GX_ALWAYS)";
    case NameGroup::AlphaOp:
      return "an alpha-test operation (GX_AOP_*)";
    case NameGroup::BlendMode:
      return "a blend mode (GX_BM_*)";
    case NameGroup::BlendFactor:
      return "a blend factor (GX_BL_*)";
    case NameGroup::LogicOp:
      return "a logic operation (GX_LO_*)";
    case NameGroup::VtxAttr:
      return "a vertex attribute (GX_VA_*)";
    case NameGroup::VtxAttrType:
      return "an attribute type (GX_NONE, GX_DIRECT)";
    case NameGroup::VtxFmt:
      return "a vertex format (GX_VTXFMT0..7)";
    case NameGroup::CompCount:
      return "a component count (GX_POS_XYZ, GX_NRM_XYZ, GX_CLR_RGBA, GX_TEX_S, ...)";
    case NameGroup::CompType:
      return "a component type (GX_F32, GX_RGBA8, ...)";
    case NameGroup::TexFormat:
      return "a texture format (GX_TF_*)";
    case NameGroup::TexWrap:
      return "a wrap mode (GX_CLAMP, GX_REPEAT, GX_MIRROR)";
    case NameGroup::TexFilter:
      return "a filter (GX_NEAR, GX_LINEAR, ...)";
    case NameGroup::Anisotropy:
      return "a maximum anisotropy (GX_ANISO_1, GX_ANISO_2, GX_ANISO_4)";
    case NameGroup::TlutFormat:
      return "a TLUT format (GX_TL_IA8, GX_TL_RGB565, GX_TL_RGB5A3)";
    case NameGroup::TlutName:
      return "a TLUT (GX_TLUT0..15, GX_BIGTLUT0..3)";
  }
  return "a GX constant";
}

}  // namespace lt::gx
