#include "paths/gx/program/gx_names.h"

#include <unordered_map>

namespace lt::gx {

namespace {

// Values as libogc defines them [OGC gc/ogc/gx.h]; a name may appear in two groups only where
// gx.h gives two spellings of one thing (GX_BL_SRCCLR / GX_BL_DSTCLR, GX_TEV_COMP_RGB8 / A8).
constexpr GxName kNames[] = {
    {"GX_FALSE", 0, NameGroup::Bool},
    {"GX_TRUE", 1, NameGroup::Bool},
    {"GX_DISABLE", 0, NameGroup::Bool},
    {"GX_ENABLE", 1, NameGroup::Bool},
    {"GX_COLOR0", 0, NameGroup::Channel},
    {"GX_COLOR1", 1, NameGroup::Channel},
    {"GX_ALPHA0", 2, NameGroup::Channel},
    {"GX_ALPHA1", 3, NameGroup::Channel},
    {"GX_COLOR0A0", 4, NameGroup::Channel},
    {"GX_COLOR1A1", 5, NameGroup::Channel},
    {"GX_COLORZERO", 6, NameGroup::Channel},
    {"GX_ALPHA_BUMP", 7, NameGroup::Channel},
    {"GX_ALPHA_BUMPN", 8, NameGroup::Channel},
    {"GX_COLORNULL", 0xff, NameGroup::Channel},
    {"GX_SRC_REG", 0, NameGroup::ColorSource},
    {"GX_SRC_VTX", 1, NameGroup::ColorSource},
    {"GX_LIGHT0", 0x001, NameGroup::Light},
    {"GX_LIGHT1", 0x002, NameGroup::Light},
    {"GX_LIGHT2", 0x004, NameGroup::Light},
    {"GX_LIGHT3", 0x008, NameGroup::Light},
    {"GX_LIGHT4", 0x010, NameGroup::Light},
    {"GX_LIGHT5", 0x020, NameGroup::Light},
    {"GX_LIGHT6", 0x040, NameGroup::Light},
    {"GX_LIGHT7", 0x080, NameGroup::Light},
    {"GX_LIGHTNULL", 0x000, NameGroup::Light},
    {"GX_DF_NONE", 0, NameGroup::DiffuseFn},
    {"GX_DF_SIGNED", 1, NameGroup::DiffuseFn},
    {"GX_DF_CLAMP", 2, NameGroup::DiffuseFn},
    {"GX_AF_SPEC", 0, NameGroup::AttnFn},
    {"GX_AF_SPOT", 1, NameGroup::AttnFn},
    {"GX_AF_NONE", 2, NameGroup::AttnFn},
    {"GX_SP_OFF", 0, NameGroup::SpotFn},
    {"GX_SP_FLAT", 1, NameGroup::SpotFn},
    {"GX_SP_COS", 2, NameGroup::SpotFn},
    {"GX_SP_COS2", 3, NameGroup::SpotFn},
    {"GX_SP_SHARP", 4, NameGroup::SpotFn},
    {"GX_SP_RING1", 5, NameGroup::SpotFn},
    {"GX_SP_RING2", 6, NameGroup::SpotFn},
    {"GX_DA_OFF", 0, NameGroup::DistFn},
    {"GX_DA_GENTLE", 1, NameGroup::DistFn},
    {"GX_DA_MEDIUM", 2, NameGroup::DistFn},
    {"GX_DA_STEEP", 3, NameGroup::DistFn},
    {"GX_TEXCOORD0", 0, NameGroup::TexCoord},
    {"GX_TEXCOORD1", 1, NameGroup::TexCoord},
    {"GX_TEXCOORD2", 2, NameGroup::TexCoord},
    {"GX_TEXCOORD3", 3, NameGroup::TexCoord},
    {"GX_TEXCOORD4", 4, NameGroup::TexCoord},
    {"GX_TEXCOORD5", 5, NameGroup::TexCoord},
    {"GX_TEXCOORD6", 6, NameGroup::TexCoord},
    {"GX_TEXCOORD7", 7, NameGroup::TexCoord},
    {"GX_TEXCOORDNULL", 0xff, NameGroup::TexCoord},
    {"GX_TEXMAP0", 0, NameGroup::TexMap},
    {"GX_TEXMAP1", 1, NameGroup::TexMap},
    {"GX_TEXMAP2", 2, NameGroup::TexMap},
    {"GX_TEXMAP3", 3, NameGroup::TexMap},
    {"GX_TEXMAP4", 4, NameGroup::TexMap},
    {"GX_TEXMAP5", 5, NameGroup::TexMap},
    {"GX_TEXMAP6", 6, NameGroup::TexMap},
    {"GX_TEXMAP7", 7, NameGroup::TexMap},
    {"GX_TEXMAP_NULL", 0xff, NameGroup::TexMap},
    {"GX_TEXMAP_DISABLE", 0x100, NameGroup::TexMap},
    {"GX_TEVSTAGE0", 0, NameGroup::TevStage},
    {"GX_TEVSTAGE1", 1, NameGroup::TevStage},
    {"GX_TEVSTAGE2", 2, NameGroup::TevStage},
    {"GX_TEVSTAGE3", 3, NameGroup::TevStage},
    {"GX_TEVSTAGE4", 4, NameGroup::TevStage},
    {"GX_TEVSTAGE5", 5, NameGroup::TevStage},
    {"GX_TEVSTAGE6", 6, NameGroup::TevStage},
    {"GX_TEVSTAGE7", 7, NameGroup::TevStage},
    {"GX_TEVSTAGE8", 8, NameGroup::TevStage},
    {"GX_TEVSTAGE9", 9, NameGroup::TevStage},
    {"GX_TEVSTAGE10", 10, NameGroup::TevStage},
    {"GX_TEVSTAGE11", 11, NameGroup::TevStage},
    {"GX_TEVSTAGE12", 12, NameGroup::TevStage},
    {"GX_TEVSTAGE13", 13, NameGroup::TevStage},
    {"GX_TEVSTAGE14", 14, NameGroup::TevStage},
    {"GX_TEVSTAGE15", 15, NameGroup::TevStage},
    {"GX_CC_CPREV", 0, NameGroup::ColorArg},
    {"GX_CC_APREV", 1, NameGroup::ColorArg},
    {"GX_CC_C0", 2, NameGroup::ColorArg},
    {"GX_CC_A0", 3, NameGroup::ColorArg},
    {"GX_CC_C1", 4, NameGroup::ColorArg},
    {"GX_CC_A1", 5, NameGroup::ColorArg},
    {"GX_CC_C2", 6, NameGroup::ColorArg},
    {"GX_CC_A2", 7, NameGroup::ColorArg},
    {"GX_CC_TEXC", 8, NameGroup::ColorArg},
    {"GX_CC_TEXA", 9, NameGroup::ColorArg},
    {"GX_CC_RASC", 10, NameGroup::ColorArg},
    {"GX_CC_RASA", 11, NameGroup::ColorArg},
    {"GX_CC_ONE", 12, NameGroup::ColorArg},
    {"GX_CC_HALF", 13, NameGroup::ColorArg},
    {"GX_CC_KONST", 14, NameGroup::ColorArg},
    {"GX_CC_ZERO", 15, NameGroup::ColorArg},
    {"GX_CA_APREV", 0, NameGroup::AlphaArg},
    {"GX_CA_A0", 1, NameGroup::AlphaArg},
    {"GX_CA_A1", 2, NameGroup::AlphaArg},
    {"GX_CA_A2", 3, NameGroup::AlphaArg},
    {"GX_CA_TEXA", 4, NameGroup::AlphaArg},
    {"GX_CA_RASA", 5, NameGroup::AlphaArg},
    {"GX_CA_KONST", 6, NameGroup::AlphaArg},
    {"GX_CA_ZERO", 7, NameGroup::AlphaArg},
    {"GX_TEV_ADD", 0, NameGroup::TevOp},
    {"GX_TEV_SUB", 1, NameGroup::TevOp},
    {"GX_TEV_COMP_R8_GT", 8, NameGroup::TevOp},
    {"GX_TEV_COMP_R8_EQ", 9, NameGroup::TevOp},
    {"GX_TEV_COMP_GR16_GT", 10, NameGroup::TevOp},
    {"GX_TEV_COMP_GR16_EQ", 11, NameGroup::TevOp},
    {"GX_TEV_COMP_BGR24_GT", 12, NameGroup::TevOp},
    {"GX_TEV_COMP_BGR24_EQ", 13, NameGroup::TevOp},
    {"GX_TEV_COMP_RGB8_GT", 14, NameGroup::TevOp},
    {"GX_TEV_COMP_RGB8_EQ", 15, NameGroup::TevOp},
    {"GX_TEV_COMP_A8_GT", 14, NameGroup::TevOp},
    {"GX_TEV_COMP_A8_EQ", 15, NameGroup::TevOp},
    {"GX_TB_ZERO", 0, NameGroup::TevBias},
    {"GX_TB_ADDHALF", 1, NameGroup::TevBias},
    {"GX_TB_SUBHALF", 2, NameGroup::TevBias},
    {"GX_CS_SCALE_1", 0, NameGroup::TevScale},
    {"GX_CS_SCALE_2", 1, NameGroup::TevScale},
    {"GX_CS_SCALE_4", 2, NameGroup::TevScale},
    {"GX_CS_DIVIDE_2", 3, NameGroup::TevScale},
    {"GX_TEVPREV", 0, NameGroup::TevReg},
    {"GX_TEVREG0", 1, NameGroup::TevReg},
    {"GX_TEVREG1", 2, NameGroup::TevReg},
    {"GX_TEVREG2", 3, NameGroup::TevReg},
    {"GX_KCOLOR0", 0, NameGroup::KColor},
    {"GX_KCOLOR1", 1, NameGroup::KColor},
    {"GX_KCOLOR2", 2, NameGroup::KColor},
    {"GX_KCOLOR3", 3, NameGroup::KColor},
    {"GX_TEV_KCSEL_1", 0x00, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_7_8", 0x01, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_3_4", 0x02, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_5_8", 0x03, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_1_2", 0x04, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_3_8", 0x05, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_1_4", 0x06, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_1_8", 0x07, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K0", 0x0C, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K1", 0x0D, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K2", 0x0E, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K3", 0x0F, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K0_R", 0x10, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K1_R", 0x11, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K2_R", 0x12, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K3_R", 0x13, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K0_G", 0x14, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K1_G", 0x15, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K2_G", 0x16, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K3_G", 0x17, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K0_B", 0x18, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K1_B", 0x19, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K2_B", 0x1A, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K3_B", 0x1B, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K0_A", 0x1C, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K1_A", 0x1D, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K2_A", 0x1E, NameGroup::KColorSel},
    {"GX_TEV_KCSEL_K3_A", 0x1F, NameGroup::KColorSel},
    {"GX_TEV_KASEL_1", 0x00, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_7_8", 0x01, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_3_4", 0x02, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_5_8", 0x03, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_1_2", 0x04, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_3_8", 0x05, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_1_4", 0x06, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_1_8", 0x07, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K0_R", 0x10, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K1_R", 0x11, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K2_R", 0x12, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K3_R", 0x13, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K0_G", 0x14, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K1_G", 0x15, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K2_G", 0x16, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K3_G", 0x17, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K0_B", 0x18, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K1_B", 0x19, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K2_B", 0x1A, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K3_B", 0x1B, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K0_A", 0x1C, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K1_A", 0x1D, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K2_A", 0x1E, NameGroup::KAlphaSel},
    {"GX_TEV_KASEL_K3_A", 0x1F, NameGroup::KAlphaSel},
    {"GX_MODULATE", 0, NameGroup::TevMode},
    {"GX_DECAL", 1, NameGroup::TevMode},
    {"GX_BLEND", 2, NameGroup::TevMode},
    {"GX_REPLACE", 3, NameGroup::TevMode},
    {"GX_PASSCLR", 4, NameGroup::TevMode},
    {"GX_TEV_SWAP0", 0, NameGroup::Swap},
    {"GX_TEV_SWAP1", 1, NameGroup::Swap},
    {"GX_TEV_SWAP2", 2, NameGroup::Swap},
    {"GX_TEV_SWAP3", 3, NameGroup::Swap},
    {"GX_CH_RED", 0, NameGroup::ColorComponent},
    {"GX_CH_GREEN", 1, NameGroup::ColorComponent},
    {"GX_CH_BLUE", 2, NameGroup::ColorComponent},
    {"GX_CH_ALPHA", 3, NameGroup::ColorComponent},
    {"GX_TG_MTX3x4", 0, NameGroup::TexGenType},
    {"GX_TG_MTX2x4", 1, NameGroup::TexGenType},
    {"GX_TG_POS", 0, NameGroup::TexGenSource},
    {"GX_TG_NRM", 1, NameGroup::TexGenSource},
    {"GX_TG_BINRM", 2, NameGroup::TexGenSource},
    {"GX_TG_TANGENT", 3, NameGroup::TexGenSource},
    {"GX_TG_TEX0", 4, NameGroup::TexGenSource},
    {"GX_TG_TEX1", 5, NameGroup::TexGenSource},
    {"GX_TG_TEX2", 6, NameGroup::TexGenSource},
    {"GX_TG_TEX3", 7, NameGroup::TexGenSource},
    {"GX_TG_TEX4", 8, NameGroup::TexGenSource},
    {"GX_TG_TEX5", 9, NameGroup::TexGenSource},
    {"GX_TG_TEX6", 10, NameGroup::TexGenSource},
    {"GX_TG_TEX7", 11, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD0", 12, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD1", 13, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD2", 14, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD3", 15, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD4", 16, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD5", 17, NameGroup::TexGenSource},
    {"GX_TG_TEXCOORD6", 18, NameGroup::TexGenSource},
    {"GX_TG_COLOR0", 19, NameGroup::TexGenSource},
    {"GX_TG_COLOR1", 20, NameGroup::TexGenSource},
    {"GX_TEXMTX0", 30, NameGroup::TexMtx},
    {"GX_TEXMTX1", 33, NameGroup::TexMtx},
    {"GX_TEXMTX2", 36, NameGroup::TexMtx},
    {"GX_TEXMTX3", 39, NameGroup::TexMtx},
    {"GX_TEXMTX4", 42, NameGroup::TexMtx},
    {"GX_TEXMTX5", 45, NameGroup::TexMtx},
    {"GX_TEXMTX6", 48, NameGroup::TexMtx},
    {"GX_TEXMTX7", 51, NameGroup::TexMtx},
    {"GX_TEXMTX8", 54, NameGroup::TexMtx},
    {"GX_TEXMTX9", 57, NameGroup::TexMtx},
    {"GX_IDENTITY", 60, NameGroup::TexMtx},
    {"GX_MTX3x4", 0, NameGroup::MtxType},
    {"GX_MTX2x4", 1, NameGroup::MtxType},
    {"GX_CULL_NONE", 0, NameGroup::CullMode},
    {"GX_CULL_FRONT", 1, NameGroup::CullMode},
    {"GX_CULL_BACK", 2, NameGroup::CullMode},
    {"GX_CULL_ALL", 3, NameGroup::CullMode},
    {"GX_NEVER", 0, NameGroup::Compare},
    {"GX_LESS", 1, NameGroup::Compare},
    {"GX_EQUAL", 2, NameGroup::Compare},
    {"GX_LEQUAL", 3, NameGroup::Compare},
    {"GX_GREATER", 4, NameGroup::Compare},
    {"GX_NEQUAL", 5, NameGroup::Compare},
    {"GX_GEQUAL", 6, NameGroup::Compare},
    {"GX_ALWAYS", 7, NameGroup::Compare},
    {"GX_AOP_AND", 0, NameGroup::AlphaOp},
    {"GX_AOP_OR", 1, NameGroup::AlphaOp},
    {"GX_AOP_XOR", 2, NameGroup::AlphaOp},
    {"GX_AOP_XNOR", 3, NameGroup::AlphaOp},
    {"GX_BM_NONE", 0, NameGroup::BlendMode},
    {"GX_BM_BLEND", 1, NameGroup::BlendMode},
    {"GX_BM_LOGIC", 2, NameGroup::BlendMode},
    {"GX_BM_SUBTRACT", 3, NameGroup::BlendMode},
    {"GX_BL_ZERO", 0, NameGroup::BlendFactor},
    {"GX_BL_ONE", 1, NameGroup::BlendFactor},
    {"GX_BL_SRCCLR", 2, NameGroup::BlendFactor},
    {"GX_BL_INVSRCCLR", 3, NameGroup::BlendFactor},
    {"GX_BL_SRCALPHA", 4, NameGroup::BlendFactor},
    {"GX_BL_INVSRCALPHA", 5, NameGroup::BlendFactor},
    {"GX_BL_DSTALPHA", 6, NameGroup::BlendFactor},
    {"GX_BL_INVDSTALPHA", 7, NameGroup::BlendFactor},
    {"GX_BL_DSTCLR", 2, NameGroup::BlendFactor},
    {"GX_BL_INVDSTCLR", 3, NameGroup::BlendFactor},
    {"GX_LO_CLEAR", 0, NameGroup::LogicOp},
    {"GX_LO_AND", 1, NameGroup::LogicOp},
    {"GX_LO_REVAND", 2, NameGroup::LogicOp},
    {"GX_LO_COPY", 3, NameGroup::LogicOp},
    {"GX_LO_INVAND", 4, NameGroup::LogicOp},
    {"GX_LO_NOOP", 5, NameGroup::LogicOp},
    {"GX_LO_XOR", 6, NameGroup::LogicOp},
    {"GX_LO_OR", 7, NameGroup::LogicOp},
    {"GX_LO_NOR", 8, NameGroup::LogicOp},
    {"GX_LO_EQUIV", 9, NameGroup::LogicOp},
    {"GX_LO_INV", 10, NameGroup::LogicOp},
    {"GX_LO_REVOR", 11, NameGroup::LogicOp},
    {"GX_LO_INVCOPY", 12, NameGroup::LogicOp},
    {"GX_LO_INVOR", 13, NameGroup::LogicOp},
    {"GX_LO_NAND", 14, NameGroup::LogicOp},
    {"GX_LO_SET", 15, NameGroup::LogicOp},
    {"GX_VA_PTNMTXIDX", 0, NameGroup::VtxAttr},
    {"GX_VA_TEX0MTXIDX", 1, NameGroup::VtxAttr},
    {"GX_VA_TEX1MTXIDX", 2, NameGroup::VtxAttr},
    {"GX_VA_TEX2MTXIDX", 3, NameGroup::VtxAttr},
    {"GX_VA_TEX3MTXIDX", 4, NameGroup::VtxAttr},
    {"GX_VA_TEX4MTXIDX", 5, NameGroup::VtxAttr},
    {"GX_VA_TEX5MTXIDX", 6, NameGroup::VtxAttr},
    {"GX_VA_TEX6MTXIDX", 7, NameGroup::VtxAttr},
    {"GX_VA_TEX7MTXIDX", 8, NameGroup::VtxAttr},
    {"GX_VA_POS", 9, NameGroup::VtxAttr},
    {"GX_VA_NRM", 10, NameGroup::VtxAttr},
    {"GX_VA_CLR0", 11, NameGroup::VtxAttr},
    {"GX_VA_CLR1", 12, NameGroup::VtxAttr},
    {"GX_VA_TEX0", 13, NameGroup::VtxAttr},
    {"GX_VA_TEX1", 14, NameGroup::VtxAttr},
    {"GX_VA_TEX2", 15, NameGroup::VtxAttr},
    {"GX_VA_TEX3", 16, NameGroup::VtxAttr},
    {"GX_VA_TEX4", 17, NameGroup::VtxAttr},
    {"GX_VA_TEX5", 18, NameGroup::VtxAttr},
    {"GX_VA_TEX6", 19, NameGroup::VtxAttr},
    {"GX_VA_TEX7", 20, NameGroup::VtxAttr},
    {"GX_NONE", 0, NameGroup::VtxAttrType},
    {"GX_DIRECT", 1, NameGroup::VtxAttrType},
    {"GX_INDEX8", 2, NameGroup::VtxAttrType},
    {"GX_INDEX16", 3, NameGroup::VtxAttrType},
    {"GX_VTXFMT0", 0, NameGroup::VtxFmt},
    {"GX_VTXFMT1", 1, NameGroup::VtxFmt},
    {"GX_VTXFMT2", 2, NameGroup::VtxFmt},
    {"GX_VTXFMT3", 3, NameGroup::VtxFmt},
    {"GX_VTXFMT4", 4, NameGroup::VtxFmt},
    {"GX_VTXFMT5", 5, NameGroup::VtxFmt},
    {"GX_VTXFMT6", 6, NameGroup::VtxFmt},
    {"GX_VTXFMT7", 7, NameGroup::VtxFmt},
    {"GX_POS_XY", 0, NameGroup::CompCount},
    {"GX_POS_XYZ", 1, NameGroup::CompCount},
    {"GX_NRM_XYZ", 0, NameGroup::CompCount},
    {"GX_NRM_NBT", 1, NameGroup::CompCount},
    {"GX_NRM_NBT3", 2, NameGroup::CompCount},
    {"GX_CLR_RGB", 0, NameGroup::CompCount},
    {"GX_CLR_RGBA", 1, NameGroup::CompCount},
    {"GX_TEX_S", 0, NameGroup::CompCount},
    {"GX_TEX_ST", 1, NameGroup::CompCount},
    {"GX_U8", 0, NameGroup::CompType},
    {"GX_S8", 1, NameGroup::CompType},
    {"GX_U16", 2, NameGroup::CompType},
    {"GX_S16", 3, NameGroup::CompType},
    {"GX_F32", 4, NameGroup::CompType},
    {"GX_RGB565", 0, NameGroup::CompType},
    {"GX_RGB8", 1, NameGroup::CompType},
    {"GX_RGBX8", 2, NameGroup::CompType},
    {"GX_RGBA4", 3, NameGroup::CompType},
    {"GX_RGBA6", 4, NameGroup::CompType},
    {"GX_RGBA8", 5, NameGroup::CompType},
    {"GX_TF_I4", 0x0, NameGroup::TexFormat},
    {"GX_TF_I8", 0x1, NameGroup::TexFormat},
    {"GX_TF_IA4", 0x2, NameGroup::TexFormat},
    {"GX_TF_IA8", 0x3, NameGroup::TexFormat},
    {"GX_TF_RGB565", 0x4, NameGroup::TexFormat},
    {"GX_TF_RGB5A3", 0x5, NameGroup::TexFormat},
    {"GX_TF_RGBA8", 0x6, NameGroup::TexFormat},
    {"GX_TF_CI4", 0x8, NameGroup::TexFormat},
    {"GX_TF_CI8", 0x9, NameGroup::TexFormat},
    {"GX_TF_CI14", 0xa, NameGroup::TexFormat},
    {"GX_TF_CMPR", 0xE, NameGroup::TexFormat},
    {"GX_CLAMP", 0, NameGroup::TexWrap},
    {"GX_REPEAT", 1, NameGroup::TexWrap},
    {"GX_MIRROR", 2, NameGroup::TexWrap},
    {"GX_NEAR", 0, NameGroup::TexFilter},
    {"GX_LINEAR", 1, NameGroup::TexFilter},
    {"GX_NEAR_MIP_NEAR", 2, NameGroup::TexFilter},
    {"GX_LIN_MIP_NEAR", 3, NameGroup::TexFilter},
    {"GX_NEAR_MIP_LIN", 4, NameGroup::TexFilter},
    {"GX_LIN_MIP_LIN", 5, NameGroup::TexFilter},
    {"GX_PNMTX0", 0, NameGroup::PosMtx},
    {"GX_PNMTX1", 3, NameGroup::PosMtx},
    {"GX_PNMTX2", 6, NameGroup::PosMtx},
    {"GX_PNMTX3", 9, NameGroup::PosMtx},
    {"GX_PNMTX4", 12, NameGroup::PosMtx},
    {"GX_PNMTX5", 15, NameGroup::PosMtx},
    {"GX_PNMTX6", 18, NameGroup::PosMtx},
    {"GX_PNMTX7", 21, NameGroup::PosMtx},
    {"GX_PNMTX8", 24, NameGroup::PosMtx},
    {"GX_PNMTX9", 27, NameGroup::PosMtx},
};

}  // namespace

const GxName* find_gx_name(std::string_view name) {
  static const std::unordered_map<std::string_view, const GxName*> index = [] {
    std::unordered_map<std::string_view, const GxName*> m;
    for (const GxName& n : kNames) m.emplace(n.name, &n);
    return m;
  }();
  const auto it = index.find(name);
  return it == index.end() ? nullptr : it->second;
}

std::string gx_name_of(NameGroup group, long long value) {
  for (const GxName& n : kNames) {
    if (n.group == group && n.value == value) return n.name;
  }
  return "";
}

std::string describe(NameGroup group) {
  switch (group) {
    case NameGroup::PosMtx:
      return "a position matrix (GX_PNMTX0..9)";
    case NameGroup::CullMode:
      return "a cull mode (GX_CULL_*)";
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
  }
  return "a GX constant";
}

}  // namespace lt::gx
