// GX program files shared by the gx tests.
#pragma once

namespace lt::gx::test_programs {

// gx.md §1's example, as a porter writes it (plus GX_SetNumTexGens(0): it samples nothing, and
// GX_SetCullMode(GX_CULL_NONE): GX_Init's GX_CULL_BACK would cull the test quads, which are wound
// counter-clockwise as GL's front faces). Lighting is off, so every covered pixel is RASC * K0 in
// TEV arithmetic.
inline constexpr const char* kFlatColour = R"(// a flat-coloured stage
GX_SetCullMode(GX_CULL_NONE);
GX_SetNumChans(1);
GX_SetChanCtrl(GX_COLOR0A0, GX_DISABLE, GX_SRC_REG, GX_SRC_REG, GX_LIGHTNULL, GX_DF_NONE, GX_AF_NONE);
GX_SetChanMatColor(GX_COLOR0A0, (GXColor){200, 120, 40, 255});
GX_SetNumTexGens(0);
GX_SetNumTevStages(1);
GX_SetTevOrder(GX_TEVSTAGE0, GX_TEXCOORDNULL, GX_TEXMAP_NULL, GX_COLOR0A0);
GX_SetTevColorIn(GX_TEVSTAGE0, GX_CC_ZERO, GX_CC_RASC, GX_CC_KONST, GX_CC_ZERO);
GX_SetTevColorOp(GX_TEVSTAGE0, GX_TEV_ADD, GX_TB_ZERO, GX_CS_SCALE_1, GX_TRUE, GX_TEVPREV);
GX_SetTevKColor(GX_KCOLOR0, (GXColor){128, 64, 255, 255});
GX_SetTevKColorSel(GX_TEVSTAGE0, GX_TEV_KCSEL_K0);
)";

}  // namespace lt::gx::test_programs
