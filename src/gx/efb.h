// The embedded framebuffer (EFB) end of the pipeline: the alpha test, the blend of a pass onto
// what earlier passes left, and the store of the TEV's output (gx-hardware.md §1.5).
#pragma once

#include <vector>

#include "gx/gx_types.h"

namespace lt::gx {

// The EFB of one frame as Dolphin's software renderer keeps it [DSW EfbInterface.cpp
// GetColorOffset, GetDepthOffset, SetPixelDepth]: per pixel 24 bits of colour in the frame's
// pixel format (held here as the colour it reads back as: efb_stored) and 24 bits of depth, rows
// top first as GX numbers them; and, for the image's alpha, which pixels some triangle covered
// (passed the edge and scissor tests, whatever z and the alpha test then did). One pixel format
// a frame (gx_path.h scene_programs_for): a format changed between draws would reinterpret the
// stored bits, which the emulator does not model.
struct Efb {
  int width = 0, height = 0;
  u8 pixel_format = kPixelRgb8Z24;
  std::vector<Color8> color;
  std::vector<u32> depth;
  std::vector<u8> covered;
  // The frame's clearing copy: every pixel the clear colour and z (GX_SetCopyClear [OGC gx.c
  // L1891-1903]) as `pixel_format` stores them (the clear writes no dither [DSW SetColor]),
  // nothing covered.
  void clear(int w, int h, const Color8& clear_color, u32 clear_z, u8 format = kPixelRgb8Z24);
};

// What the EFB reads back of a colour written in `pixel_format` (kPixel*, gx_types.h) [DSW
// SWEfbInterface.cpp SetPixelAlphaColor, GetPixelColor]: RGB8_Z24 keeps r, g, b and no alpha,
// which reads back as 255; RGBA6_Z24 keeps the top 6 bits of r, g, b and a, read back as
// Convert6To8 (v << 2 | v >> 4); RGB565_Z16 is stored as RGB8_Z24 by Dolphin's software
// renderer ("RGB565_Z16 is not supported correctly yet"), so here too (the console keeps 5, 6
// and 5 bits: docs/spec/gx-hardware.md).
Color8 efb_stored(u8 pixel_format, const Color8& c);

// The blend unit's output as the colour update writes it at pixel (x, y) [DSW BlendTev, Dither]:
// with dithering on and RGBA6_Z24, r, g and b get the 2x2 Bayer offset {{0, 2}, {3, 1}} of the
// pixel's row and column parity, "((c - (c >> 6)) + d) & 0xfc" (alpha is not dithered); then
// the format's storage (efb_stored).
Color8 efb_written(u8 pixel_format, bool dither, int x, int y, const Color8& c);

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

// The colour the blend unit gives for `src` drawn over `dst` (the EFB's colour as it reads back:
// efb_stored), all four channels as Dolphin computes them: GX_BM_NONE is src; GX_BM_BLEND
// computes min((src*sf' + dst*df') >> 8, 255) per channel with f' = f + (f >> 7) [DSW
// BlendColor], so ONE/ONE is min(src + dst, 255); GX_BM_SUBTRACT is max(dst - src, 0) and
// GX_BM_LOGIC the 16 bitwise GX_LO_* operations on the 8-bit values [DSW SubtractBlend,
// LogicBlend]. What the EFB keeps of the result is its pixel format's business (efb_written).
Color8 blend(const BlendMode& mode, const Color8& src, const Color8& dst);

}  // namespace lt::gx
