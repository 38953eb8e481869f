#include "gx/gx_state.h"

namespace lt::gx {

GxState::GxState() {
  // GX_Init's TEV [OGC gx.c __GX_InitGX]: stages 0..7 fetch TEXCOORDn / TEXMAPn with COLOR0A0,
  // stages 8..15 nothing; one stage, set to GX_REPLACE (colour TEXC, alpha TEXA, add, clamp,
  // PREV). The combiners of stages 1..15 are not written by GX_Init: they are modelled as
  // zeroed registers (all inputs CPREV/APREV, add, no clamp, PREV).
  for (int s = 0; s < kMaxTevStages; ++s) {
    TevStage& st = tev.stages[static_cast<size_t>(s)];
    st.texcoord = s < 8 ? static_cast<u8>(s) : kTexCoordNull;
    st.texmap = s < 8 ? static_cast<u8>(s) : kTexMapNull;
    st.channel = s < 8 ? 4 : kColorNull;
    st.color = TevCombiner{0, 0, 0, 0, 0, 0, 0, false, 0};
    st.alpha = TevCombiner{0, 0, 0, 0, 0, 0, 0, false, 0};
  }
  TevStage& first = tev.stages[0];
  first.color = TevCombiner{15, 15, 15, 8, 0, 0, 0, true, 0};  // ZERO, ZERO, ZERO, TEXC
  first.alpha = TevCombiner{7, 7, 7, 4, 0, 0, 0, true, 0};     // ZERO, ZERO, ZERO, TEXA
  // GX_SetChanCtrl(GX_COLORnAn, GX_DISABLE, GX_SRC_REG, GX_SRC_VTX, GX_LIGHTNULL, GX_DF_NONE,
  // GX_AF_NONE) for both channels: ChannelControl's defaults.
}

std::array<TexCoordScale, kMaxTexGens> texcoord_scales(
    const GxState& state, const std::array<const TextureObject*, kMaxTexMaps>& textures) {
  std::array<TexCoordScale, kMaxTexGens> out{};
  for (int st = 0; st < state.tev.num_stages; ++st) {
    const TevStage& stage = state.tev.stages[static_cast<size_t>(st)];
    if (stage.texmap == kTexMapNull) continue;
    const u8 coord = stage.texcoord == kTexCoordNull ? 0 : stage.texcoord;
    const TextureObject* t = textures[stage.texmap & 7];
    if (coord >= kMaxTexGens || !t) continue;
    out[coord] = {static_cast<u32>(t->width), static_cast<u32>(t->height), t->wrap_s, t->wrap_t};
  }
  return out;
}

}  // namespace lt::gx
