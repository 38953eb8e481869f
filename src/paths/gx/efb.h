// The embedded framebuffer (EFB) end of the pipeline: the alpha test, the blend of a pass onto
// what earlier passes left, and the store of the TEV's output (gx-hardware.md §1.5).
#pragma once

#include <vector>

#include "paths/gx/gx_types.h"

namespace lt::gx {

// The EFB of one frame as Dolphin's software renderer keeps it for RGB8_Z24 [DSW EfbInterface.cpp
// GetColorOffset, GetDepthOffset, SetPixelDepth]: per pixel 24 bits of colour (alpha reads 255,
// `GetPixelColor`) and 24 bits of depth, rows top first as GX numbers them; and, for the image's
// alpha, which pixels some triangle covered (passed the edge and scissor tests, whatever z and
// the alpha test then did).
struct Efb {
  int width = 0, height = 0;
  std::vector<Color8> color;
  std::vector<u32> depth;
  std::vector<u8> covered;
  // The frame's clearing copy: every pixel the clear colour and z (GX_SetCopyClear [OGC gx.c
  // L1891-1903]), nothing covered.
  void clear(int w, int h, const Color8& clear_color, u32 clear_z);
};

// GX_SetZMode's compare GX_NEVER .. GX_ALWAYS (0..7) of the incoming z against the stored
// depth [DSW EfbInterface.cpp ZCompare]; both are 24-bit (an incoming z of Dolphin's INT_MIN,
// from a NaN, is 0x80000000 and compares as that).
bool z_compare(u8 func, u32 z, u32 depth);

// GX_SetAlphaCompare(comp0, ref0, op, comp1, ref1) [OGC gx.h L3106]. GX_Init: ALWAYS/AND/ALWAYS.
struct AlphaCompare {
  u8 comp0 = 7, ref0 = 0, op = 0, comp1 = 7, ref1 = 0;
  bool operator==(const AlphaCompare&) const = default;
};

// GX_SetBlendMode(type, src, dst, logic op) [OGC gx.h L2882]. GX_Init: GX_BM_NONE with
// SRCALPHA / INVSRCALPHA / CLEAR [OGC gx.c __GX_InitGX].
struct BlendMode {
  u8 type = 0, src = 4, dst = 5, logic = 0;
  bool operator==(const BlendMode&) const = default;
};

// The TEV output reaches the EFB as its low 8 bits: a wrap, not a clamp [HWT gxtest/util.cpp
// L357 "The TEV output gets truncated to 8 bits when writing to the EFB"].
Color8 tev_to_efb(const ColorS10& tev);

// Whether an 8-bit alpha passes the alpha test: (A comp0 ref0) op (A comp1 ref1) [DSW
// TevAlphaTest] with comp NEVER, LESS, EQUAL, LEQUAL, GREATER, NEQUAL, GEQUAL, ALWAYS (0..7) and
// op AND, OR, XOR, XNOR (0..3).
bool alpha_test(const AlphaCompare& compare, u8 alpha);

// The colour a pixel holds after `src` is drawn over `dst`: GX_BM_NONE writes src; GX_BM_BLEND
// computes min((src*sf' + dst*df') >> 8, 255) per channel with f' = f + (f >> 7) [DSW
// BlendColor], so ONE/ONE is min(src + dst, 255); GX_BM_SUBTRACT is max(dst - src, 0) and
// GX_BM_LOGIC the 16 bitwise GX_LO_* operations on the 8-bit values [DSW SubtractBlend,
// LogicBlend]. The EFB is RGB8_Z24: a destination alpha reads as 255, the result keeps src's.
Color8 blend(const BlendMode& mode, const Color8& src, const Color8& dst);

}  // namespace lt::gx
