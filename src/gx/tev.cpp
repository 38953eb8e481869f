#include "gx/tev.h"

#include <algorithm>

#include "gx/tev_arith.h"

namespace lt::gx {

namespace {

// The arithmetic lives in tev_arith.h (shared with tev_plan.cpp); its names are qualified, not
// imported, because a using-directive here would reach the next files of a unity batch.

// Konst selectors 0..7, the fractions 1, 7/8 .. 1/8 as the hardware outputs them; note 5/8 is
// 159 and 1/2 is 128, not round(255*f) [HWT gxtest/tev.cpp L338-343, PR#368].
constexpr u8 kKonstFractions[8] = {255, 223, 191, 159, 128, 96, 64, 32};

Color8 swizzle(const Color8& c, const std::array<u8, 4>& table) {
  Color8 out;
  for (int i = 0; i < 4; ++i) out[i] = c[tev_arith::bits(table[i], 2)];
  return out;
}

// RASC/RASA of a stage. libogc maps the API colour id onto the 3-bit hardware channel with
// _gxtevcolid = {0,1,0,1,0,1,7,5,6} and COLORNULL onto 7 [OGC gx.c L100, L4010-4012]: GX_COLOR0,
// GX_ALPHA0, GX_COLOR0A0 (0, 2, 4) read channel 0 and 1, 3, 5 read channel 1. 7 is the zero
// channel; 5/6 (bump alpha) read AlphaBump, which is 0 on a direct stage (GX_SetTevDirect, the
// GX_Init default [OGC gx.c L695-697]) [DSW Tev.cpp SetRasColor, Tev::Indirect].
Color8 ras_color(const TevStage& stage, const TevState& state, const TevPixelInputs& in) {
  if (stage.channel > 5) return Color8{};
  return swizzle(in.channels[stage.channel & 1],
                 state.swap_tables[tev_arith::bits(stage.ras_swap, 2)]);
}

// Everything a stage's selectors can read, fixed before the stage runs: both combiners of one
// stage read the same old register values [DSW Tev.cpp Tev::Draw builds `inputs` for colour and
// alpha before either combiner writes].
struct StageSources {
  const std::array<ColorS10, kTevRegisters>& regs;
  Color8 tex, ras;
  u8 konst_rgb[3];
  u8 konst_a;
};

// One colour selector (GX_CC_*) for component i (0 r .. 2 b). The odd register selectors and
// TEXA/RASA replicate alpha into r, g, b; ONE, HALF, ZERO are 255, 128, 0 [DSW Tev.h
// m_ColorInputLUT, V1/V1_2/V0; HALF = 128 HW-verified, HWT gxtest/tev.cpp L378].
s32 color_source(u8 selector, int i, const StageSources& s) {
  const u8 sel = tev_arith::bits(selector, 4);
  if (sel < 8) {
    const ColorS10& reg = s.regs[sel >> 1];
    return (sel & 1) ? reg.a : reg[i];
  }
  switch (static_cast<TevColorArg>(sel)) {
    case TevColorArg::TexC:
      return s.tex[i];
    case TevColorArg::TexA:
      return s.tex.a;
    case TevColorArg::RasC:
      return s.ras[i];
    case TevColorArg::RasA:
      return s.ras.a;
    case TevColorArg::One:
      return 255;
    case TevColorArg::Half:
      return 128;
    case TevColorArg::Konst:
      return s.konst_rgb[i];
    default:
      return 0;  // Zero
  }
}

// One alpha selector (GX_CA_*) [DSW Tev.h m_AlphaInputLUT].
s32 alpha_source(u8 selector, const StageSources& s) {
  const u8 sel = tev_arith::bits(selector, 3);
  if (sel < 4) return s.regs[sel].a;
  switch (static_cast<TevAlphaArg>(sel)) {
    case TevAlphaArg::TexA:
      return s.tex.a;
    case TevAlphaArg::RasA:
      return s.ras.a;
    case TevAlphaArg::Konst:
      return s.konst_a;
    default:
      return 0;  // Zero
  }
}

tev_arith::Operands color_operands(const TevCombiner& cc, int i, const StageSources& s) {
  return tev_arith::operands(color_source(cc.a, i, s), color_source(cc.b, i, s),
                             color_source(cc.c, i, s), color_source(cc.d, i, s));
}

tev_arith::Operands alpha_operands(const TevCombiner& ac, const StageSources& s) {
  return tev_arith::operands(alpha_source(ac.a, s), alpha_source(ac.b, s), alpha_source(ac.c, s),
                             alpha_source(ac.d, s));
}

}  // namespace

u8 konst_value(u8 selector, int component, const std::array<Color8, kMaxKonstColors>& konst,
               bool alpha) {
  // KCSEL/KASEL are 5-bit fields [OGC gx.c L4046-4066]; table [HWT gxtest/tev.cpp L338-343].
  const u8 sel = tev_arith::bits(selector, 5);
  if (sel < 8) return kKonstFractions[sel];
  // 8..11 "invalid ... on hardware, they all output zero" [DSW Tev.h m_KonstLUT].
  if (sel < 12) return 0;
  // 12..15 are K0..K3 .rgb; as an alpha selector they read 0 [HWT gxtest/tev.cpp L341].
  if (sel < 16) return alpha ? 0 : konst[sel - 12][component];
  // 16..31: one component of one konst replicated; r of K0..K3, then g, b, a.
  const int index = sel - 16;
  return konst[index & 3][index >> 2];
}

s16 tev_regular(int a, int b, int c, int d, u8 op, u8 bias, u8 scale, bool clamp) {
  return static_cast<s16>(
      tev_arith::apply_regular(tev_arith::regular_op(op, bias, scale, clamp), a, b, c, d));
}

ColorS10 run_tev(const TevState& state, const TevPixelInputs& in) {
  std::array<ColorS10, kTevRegisters> regs = state.registers;
  for (ColorS10& reg : regs) {
    for (int i = 0; i < 4; ++i) reg[i] = static_cast<s16>(tev_arith::wrap11(reg[i]));
  }
  // numtevstages is stored as n-1 in 4 bits [OGC gx.c L4035]: there is always at least one stage.
  const int num_stages = std::clamp(state.num_stages, 1, kMaxTevStages);

  // A stage without a texture fetch (texmap == GX_TEXMAP_NULL, enable bit clear [OGC gx.c
  // L4015, L4026]) leaves TEXC/TEXA at what the last fetching stage loaded: Dolphin's software
  // renderer only assigns TexColor inside `if (order.getEnable(stageOdd))` and never resets it
  // [DSW Tev.cpp Tev::Draw; TexColor default 0 in Tev.h]. Before any stage of the pixel has
  // fetched it reads 0. (Dolphin's shader generator writes 255 instead, 0 with no texgens [DHW
  // PixelShaderGen WriteStage]; no hardware test covers either.)
  Color8 tex{};

  for (int n = 0; n < num_stages; ++n) {
    const TevStage& stage = state.stages[n];
    if (stage.texmap != kTexMapNull) {
      // The swapped texel, with the fetching stage's tex swap table [DSW Tev.cpp Tev::Draw].
      tex = swizzle(in.texels[n], state.swap_tables[tev_arith::bits(stage.tex_swap, 2)]);
    }
    StageSources s{regs, tex, ras_color(stage, state, in), {}, 0};
    for (int i = 0; i < 3; ++i) {
      s.konst_rgb[i] = konst_value(stage.konst_color_sel, i, state.konst, false);
    }
    s.konst_a = konst_value(stage.konst_alpha_sel, 3, state.konst, true);

    const TevCombiner& cc = stage.color;
    const TevCombiner& ac = stage.alpha;
    const tev_arith::Operands col[3] = {color_operands(cc, 0, s), color_operands(cc, 1, s),
                                        color_operands(cc, 2, s)};
    const tev_arith::Operands alp = alpha_operands(ac, s);

    s32 rgb[3];
    for (int i = 0; i < 3; ++i) {
      if (tev_arith::bits(cc.bias, 2) != 3) {
        rgb[i] =
            tev_regular(col[i].a, col[i].b, col[i].c, col[i].d, cc.op, cc.bias, cc.scale, cc.clamp);
        continue;
      }
      // Compare stage [DSW Tev.cpp DrawColorCompare].
      const bool cond = tev_arith::color_condition(cc.op, tev_arith::bits(cc.scale, 2), col, i);
      rgb[i] = tev_arith::compare_result(col[i], cond, cc.clamp);
    }

    s32 alpha;
    if (tev_arith::bits(ac.bias, 2) != 3) {
      // Same equation as colour (gx-hardware.md §1.3 recommendation: HWT formula = Dolphin's
      // shader path; DSW DrawAlphaRegular's SUB floor-of-negative variant is not followed).
      alpha = tev_regular(alp.a, alp.b, alp.c, alp.d, ac.op, ac.bias, ac.scale, ac.clamp);
    } else {
      // Mode 3 is A8; the others compare the colour combiner's a and b (tev_arith.h).
      const bool cond = tev_arith::alpha_condition(ac.op, tev_arith::bits(ac.scale, 2), col, alp);
      alpha = tev_arith::compare_result(alp, cond, ac.clamp);
    }

    // Write back after both combiners have read: colour to dest.rgb, alpha to its own dest.a
    // [DSW Tev.cpp Tev::Draw].
    ColorS10& cdst = regs[tev_arith::bits(cc.dest, 2)];
    for (int i = 0; i < 3; ++i) cdst[i] = static_cast<s16>(rgb[i]);
    regs[tev_arith::bits(ac.dest, 2)].a = static_cast<s16>(alpha);
  }

  // The output is the last stage's colour dest .rgb and alpha dest .a, whatever registers they
  // are ("regardless of the used destination register" [DSW Tev.cpp Tev::Draw]; libogc requires
  // the last stage to write PREV [OGC gx.h L3057]).
  const TevStage& last = state.stages[num_stages - 1];
  ColorS10 out = regs[tev_arith::bits(last.color.dest, 2)];
  out.a = regs[tev_arith::bits(last.alpha.dest, 2)].a;
  return out;
}

}  // namespace lt::gx
