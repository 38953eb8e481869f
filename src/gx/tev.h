// The TEV (texture environment): up to 16 stages of integer colour and alpha combiners, in the
// hardware's own arithmetic (gx-hardware.md §1). Stages are kept in the hardware's register
// encoding (BP 0xC0+2n / 0xC1+2n [HWT gxtest/BPMemory.h L528-572]), so a compare stage is a
// stage whose bias field is 3, exactly as GX_SetTevColorOp writes it [OGC gx.c L3893-3909].
#pragma once

#include <array>

#include "gx/gx_types.h"

namespace lt::gx {

// Colour operand selectors, GX_CC_* [OGC gx.h L509-524].
enum class TevColorArg : u8 {
  CPrev = 0,
  APrev,
  C0,
  A0,
  C1,
  A1,
  C2,
  A2,
  TexC,
  TexA,
  RasC,
  RasA,
  One,
  Half,
  Konst,
  Zero
};
// Alpha operand selectors, GX_CA_* [OGC gx.h L533-540].
enum class TevAlphaArg : u8 { APrev = 0, A0, A1, A2, TexA, RasA, Konst, Zero };

// One combiner (colour or alpha) of one stage, as its BP register fields hold it.
struct TevCombiner {
  u8 a = 0, b = 0, c = 0, d = 0;  // operand selectors (TevColorArg or TevAlphaArg values)
  u8 bias = 0;                    // 0 zero, 1 +half (+128), 2 -half (-128), 3 = compare stage
  u8 op = 0;                      // regular: 0 add, 1 subtract; compare: 0 greater-than, 1 equal
  u8 scale = 0;       // regular: 0 x1, 1 x2, 2 x4, 3 /2; compare: 0 R8, 1 GR16, 2 BGR24, 3 RGB8/A8
  bool clamp = true;  // clamp to 0..255 (else to the 11-bit range -1024..1023)
  u8 dest = 0;        // 0 PREV, 1 REG0, 2 REG1, 3 REG2
  bool operator==(const TevCombiner&) const = default;
};

struct TevStage {
  // GX_SetTevOrder [OGC gx.h L3051]: the texcoord and texture map the stage fetches (kTexMapNull
  // for none) and the rasterised channel it reads as RASC/RASA (GX_COLOR0A0 = 4, GX_COLOR1A1 =
  // 5, GX_COLORZERO = 6, kColorNull).
  u8 texcoord = kTexCoordNull, texmap = kTexMapNull, channel = kColorNull;
  TevCombiner color, alpha;
  u8 konst_color_sel = 6;  // GX_TEV_KCSEL_1_4: GX_Init's value for every stage [OGC gx.c L686]
  u8 konst_alpha_sel = 0;  // GX_TEV_KASEL_1 [OGC gx.c L687]
  u8 ras_swap = 0, tex_swap = 0;  // swap-table indices, GX_SetTevSwapMode [OGC gx.h L3181]
  bool operator==(const TevStage&) const = default;
};

struct TevState {
  int num_stages = 1;  // GX_SetNumTevStages, 1..16
  std::array<TevStage, kMaxTevStages> stages{};
  // Initial register contents per pixel: what GX_SetTevColor/S10 last loaded [DSW Tev::Draw].
  std::array<ColorS10, kTevRegisters> registers{};
  std::array<Color8, kMaxKonstColors> konst{};
  // GX_SetTevSwapModeTable: for each of the 4 tables, the source component (0 r .. 3 a) of each
  // output component. GX_Init's tables: RGBA, RRRA, GGGA, BBBA [OGC gx.c L688-694].
  std::array<std::array<u8, 4>, 4> swap_tables{
      {{0, 1, 2, 3}, {0, 0, 0, 3}, {1, 1, 1, 3}, {2, 2, 2, 3}}};
  bool operator==(const TevState&) const = default;
};

// What one pixel brings into the TEV: the two rasterised channel colours (COLOR0A0, COLOR1A1)
// and, per stage, the filtered texel that stage fetched (ignored where the stage fetches none).
struct TevPixelInputs {
  std::array<Color8, kMaxChannels> channels{};
  std::array<Color8, kMaxTevStages> texels{};
};

// The value of a konst selector (GX_TEV_KCSEL_* / GX_TEV_KASEL_*) for one component (0 r .. 3 a),
// from the hardware-verified table [HWT gxtest/tev.cpp KonstTest L338-343]: fractions 255, 223,
// 191, 159, 128, 96, 64, 32; 8..11 give 0; 12..15 K0..K3 per component (0 for alpha); 16..31 one
// component of K0..K3 replicated.
u8 konst_value(u8 selector, int component, const std::array<Color8, kMaxKonstColors>& konst,
               bool alpha);

// One component of a regular stage (bias != 3), the hardware-verified equation of gx-hardware.md
// §1.2 [HWT gxtest/tev.cpp L16-36]. a, b, c are 0..255 (the caller has taken the low 8 bits);
// d is -1024..1023. Returns the clamped result that goes to the destination register.
s16 tev_regular(int a, int b, int c, int d, u8 op, u8 bias, u8 scale, bool clamp);

// Runs every enabled stage for one pixel and returns the last stage's destination register (11
// bits per component); the EFB keeps its low 8 bits (efb.h).
ColorS10 run_tev(const TevState& state, const TevPixelInputs& in);

}  // namespace lt::gx
