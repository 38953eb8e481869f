#include "gx/efb.h"

#include <algorithm>

// Dolphin citations are to the software renderer's EFB interface, Source/Core/VideoBackends/
// Software/EfbInterface.cpp (later renamed SWEfbInterface.cpp), by function name.

namespace lt::gx {

namespace {

// GX_NEVER .. GX_ALWAYS (0..7) [OGC gx.h L409-416]: the alpha test's and the z compare's eight
// relations of a value to its reference (3-bit fields [OGC gx.c L4042, GX_SetZMode]).
bool compare_values(u8 comp, u32 value, u32 reference) {
  switch (comp & 7) {
    case 0:
      return false;
    case 1:
      return value < reference;
    case 2:
      return value == reference;
    case 3:
      return value <= reference;
    case 4:
      return value > reference;
    case 5:
      return value != reference;
    case 6:
      return value >= reference;
    default:
      return true;
  }
}

// Dolphin's Convert6To8 [VideoCommon LookUpTables.h]: the 6 bits repeated into the low 2.
u8 convert_6_to_8(u8 v) {
  return static_cast<u8>((v << 2) | (v >> 4));
}

// One blend factor, 0..255, for channel i. Factors 2/3 are the *other* operand's colour: as a
// source factor GX_BL_SRCCLR is the destination colour (libogc even defines GX_BL_DSTCLR as
// GX_BL_SRCCLR [OGC gx.h L441-448]), as a destination factor it is the source colour (Dolphin's
// `GetSourceFactor` DstClr / `GetDestinationFactor` SrcClr).
int factor(u8 f, bool is_source, int i, const Color8& src, const Color8& dst) {
  const Color8& other = is_source ? dst : src;
  switch (f & 7) {
    case 0:
      return 0;  // GX_BL_ZERO
    case 1:
      return 255;  // GX_BL_ONE
    case 2:
      return other[i];  // GX_BL_SRCCLR / DSTCLR
    case 3:
      return 255 - other[i];  // GX_BL_INVSRCCLR / INVDSTCLR
    case 4:
      return src.a;  // GX_BL_SRCALPHA
    case 5:
      return 255 - src.a;  // GX_BL_INVSRCALPHA
    case 6:
      // GX_BL_DSTALPHA: the EFB's alpha as it reads back, 255 in RGB8_Z24 (no alpha stored);
      // libogc documents the destination-alpha factors as usable only with RGBA6_Z24 [OGC
      // gx.h L2862].
      return dst.a;
    default:
      return 255 - dst.a;  // GX_BL_INVDSTALPHA
  }
}

// f' = f + (f >> 7) maps 0..255 onto 0..256 so that ONE is an exact 1 ("add MSB of factors to
// make their range 0 -> 256" [DSW `BlendColor`]).
int widen(int f) {
  return f + (f >> 7);
}

u8 blend_channel(const BlendMode& mode, int i, const Color8& src, const Color8& dst) {
  const int sf = widen(factor(mode.src, true, i, src, dst));
  const int df = widen(factor(mode.dst, false, i, src, dst));
  return static_cast<u8>(std::min((src[i] * sf + dst[i] * df) >> 8, 255));
}

// GX_LO_CLEAR .. GX_LO_SET (0..15) [OGC gx.h L455-470], bitwise on the 8-bit values [DSW
// `LogicBlend`].
u8 logic_op(u8 op, u8 s, u8 d) {
  unsigned r = 0;
  switch (op & 15) {
    case 0:
      r = 0;
      break;  // CLEAR
    case 1:
      r = s & d;
      break;  // AND
    case 2:
      r = s & ~d;
      break;  // REVAND
    case 3:
      r = s;
      break;  // COPY
    case 4:
      r = ~s & d;
      break;  // INVAND
    case 5:
      r = d;
      break;  // NOOP
    case 6:
      r = s ^ d;
      break;  // XOR
    case 7:
      r = s | d;
      break;  // OR
    case 8:
      r = ~(s | d);
      break;  // NOR
    case 9:
      r = ~(s ^ d);
      break;  // EQUIV
    case 10:
      r = ~d;
      break;  // INV
    case 11:
      r = s | ~d;
      break;  // REVOR
    case 12:
      r = ~s;
      break;  // INVCOPY
    case 13:
      r = ~s | d;
      break;  // INVOR
    case 14:
      r = ~(s & d);
      break;  // NAND
    default:
      r = 0xff;
      break;  // SET
  }
  return static_cast<u8>(r & 0xff);
}

}  // namespace

Color8 efb_stored(u8 pixel_format, const Color8& c) {
  if (pixel_format == kPixelRgba6Z24) {
    Color8 out;
    for (int i = 0; i < 4; ++i) out[i] = convert_6_to_8(static_cast<u8>(c[i] >> 2));
    return out;
  }
  return {c.r, c.g, c.b, 255};
}

Color8 efb_written(u8 pixel_format, bool dither, int x, int y, const Color8& c) {
  if (!dither || pixel_format != kPixelRgba6Z24) return efb_stored(pixel_format, c);
  // "Flipper uses a standard 2x2 Bayer Matrix for 6 bit dithering" [DSW Dither].
  static constexpr u8 kBayer[2][2] = {{0, 2}, {3, 1}};
  const int d = kBayer[y & 1][x & 1];
  Color8 out = c;
  for (int i = 0; i < 3; ++i) out[i] = static_cast<u8>(((c[i] - (c[i] >> 6)) + d) & 0xfc);
  return efb_stored(pixel_format, out);
}

void Efb::clear(int w, int h, const Color8& clear_color, u32 clear_z, u8 format) {
  width = w;
  height = h;
  pixel_format = format;
  const size_t n = static_cast<size_t>(w) * static_cast<size_t>(h);
  color.assign(n, efb_stored(format, clear_color));
  depth.assign(n, clear_z & 0xffffff);
  covered.assign(n, 0);
}

bool z_compare(u8 func, u32 z, u32 depth) {
  return compare_values(func, z, depth);  // on 32-bit unsigned values [DSW ZCompare]
}

Color8 tev_to_efb(const ColorS10& tev) {
  Color8 out;
  for (int i = 0; i < 4; ++i) out[i] = static_cast<u8>(tev[i] & 255);
  return out;
}

bool alpha_test(const AlphaCompare& compare, u8 alpha) {
  // [DSW Tev.cpp TevAlphaTest]; op AND, OR, XOR, XNOR [OGC gx.h L682-685], 2 bits [OGC gx.c L4042].
  const bool c0 = compare_values(compare.comp0, alpha, compare.ref0);
  const bool c1 = compare_values(compare.comp1, alpha, compare.ref1);
  switch (compare.op & 3) {
    case 0:
      return c0 && c1;
    case 1:
      return c0 || c1;
    case 2:
      return c0 != c1;
    default:
      return c0 == c1;
  }
}

Color8 blend(const BlendMode& mode, const Color8& src, const Color8& dst) {
  // libogc turns the type into PE bits: BLEND and SUBTRACT set the blend enable, SUBTRACT also
  // the subtract bit, LOGIC the logic-op enable; any other type sets none [OGC gx.c L3735-3749].
  // Dolphin tests blend enable first, then logic op [DSW `BlendTev`], and blends all four
  // channels; RGB8_Z24 then stores no alpha (efb_stored).
  Color8 out = src;
  switch (mode.type) {
    case 1:  // GX_BM_BLEND: min((src*sf' + dst*df') >> 8, 255) [DSW `BlendColor`]
      for (int i = 0; i < 4; ++i) out[i] = blend_channel(mode, i, src, dst);
      break;
    case 2:  // GX_BM_LOGIC
      for (int i = 0; i < 4; ++i) out[i] = logic_op(mode.logic, src[i], dst[i]);
      break;
    case 3:  // GX_BM_SUBTRACT: dst - src clamped at 0, factors unused [DSW `SubtractBlend`;
             // OGC gx.h L2866-2870]
      for (int i = 0; i < 4; ++i) out[i] = static_cast<u8>(std::max(dst[i] - src[i], 0));
      break;
    default:  // GX_BM_NONE
      break;
  }
  return out;
}

}  // namespace lt::gx
