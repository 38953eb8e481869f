// Integer types and limits of the Wii's graphics processor (GX), shared by every unit of the gx
// path. Widths are spelled out: the point of this path is arithmetic of exactly these widths.
// Sources are cited as in docs/spec/gx-hardware.md: HWT = dolphin-emu/hwtests, OGC =
// devkitPro/libogc (gc/ogc/gx.h, libogc/gx.c), DSW = Dolphin's software renderer.
#pragma once

#include <array>
#include <cstdint>

namespace lt::gx {

using u8 = std::uint8_t;
using u16 = std::uint16_t;
using u32 = std::uint32_t;
using s16 = std::int16_t;
using s32 = std::int32_t;

// GXColor: 8 bits per component, the format of vertex colours, channel registers, light colours,
// konst colours and the EFB (RGB8_Z24, libogc's default pixel format [OGC gx.c L715]).
// The EFB's colour formats, GX_PF_* [OGC gx.h "pixel format"]: the ones a program may set
// (gx_state.h PixelFormat, efb.h).
inline constexpr u8 kPixelRgb8Z24 = 0, kPixelRgba6Z24 = 1, kPixelRgb565Z16 = 2;

struct Color8 {
  u8 r = 0, g = 0, b = 0, a = 0;
  u8& operator[](int i) { return i == 0 ? r : i == 1 ? g : i == 2 ? b : a; }
  u8 operator[](int i) const { return i == 0 ? r : i == 1 ? g : i == 2 ? b : a; }
  bool operator==(const Color8&) const = default;
};

// A TEV colour register component: an 11-bit two's-complement integer, -1024..1023
// [HWT gxtest/BPMemory.h L1827-1849]; libogc's GXColorS10 [OGC gx.c L3790-3803].
struct ColorS10 {
  s16 r = 0, g = 0, b = 0, a = 0;
  s16& operator[](int i) { return i == 0 ? r : i == 1 ? g : i == 2 ? b : a; }
  s16 operator[](int i) const { return i == 0 ? r : i == 1 ? g : i == 2 ? b : a; }
  bool operator==(const ColorS10&) const = default;
};

inline constexpr int kMaxTevStages = 16;      // [OGC gx.h L569, L3070]
inline constexpr int kMaxTexGens = 8;         // [OGC gx.h L279, L2692]
inline constexpr int kMaxTexMaps = 8;         // [OGC gx.h L673]
inline constexpr int kMaxChannels = 2;        // COLOR0A0, COLOR1A1 [OGC gx.h L3003-3011]
inline constexpr int kMaxLights = 8;          // GX_LIGHT0..7 [OGC gx.h L178-187]
inline constexpr int kMaxKonstColors = 4;     // GX_KCOLOR0..3 [OGC gx.h L692-696]
inline constexpr int kTevRegisters = 4;       // PREV, REG0..2 [OGC gx.h L637-641]
inline constexpr int kMaxTextureSize = 1024;  // per side [OGC gx.h L4263-4264]

// Covered pixels of one triangle the CPU pixel stage takes at a time in vector lanes (a run,
// raster_run.h): a multiple of every x86-64 target's 32-bit lanes (AVX-512 has 16), so each
// target runs whole vectors, and few enough that a small triangle's run wastes little.
inline constexpr int kPixelLanes = 16;

// libogc's "none" selectors [OGC gx.h]: GX_TEXCOORDNULL, GX_TEXMAP_NULL, GX_COLORNULL.
inline constexpr u8 kTexCoordNull = 0xff;
inline constexpr u8 kTexMapNull = 0xff;
inline constexpr u8 kColorNull = 0xff;

// Where the rasteriser's half-space tests sample a pixel and how finely they hold a vertex
// (rasteriser.h; the gx variant axis :coverage).
enum class CoverageRule : u8 {
  Dolphin,  // Dolphin's software renderer: vertices rounded to 1/16 pixel, samples at x + 9/16
  Console,  // the console as dolphin-emu/hwtests measured it: exact vertices, samples at x + 7/12
};

// libogc's 342 ("0x156") offset of the screen coordinates: scissor and copy rectangles start at
// it [OGC gx.c GX_SetScissor] and the viewport centre is moved by it [OGC gx.c
// GX_SetViewportJitter Yfactor].
inline constexpr u32 kScreenOffset = 342;

// The rectangle a frame draws to: the EFB origin and size (viewport, scissor, copies).
struct FrameSize {
  int width = 0, height = 0;
};

}  // namespace lt::gx
