// The GX rasteriser (gx-hardware.md §2.6): a triangle from the clipper set up as Dolphin's
// software renderer sets it up, and every pixel it covers with the values the TEV receives
// [DSW Rasterizer.cpp DrawTriangleFrontFace, SlopeContext, Slope, Draw, BuildBlock]:
// - coverage: vertices snapped to 1/16 pixel by rounding, moved by -9/16 "to match hardware
//   output", pixel centres at integer 1/16 positions, three half-space tests with the fill
//   convention's +1 (top-left rule in Dolphin's orientation), clipped to the scissor;
// - attributes: planes in float through vertex 0, evaluated at each pixel from vertex 0's pixel
//   (x0, y0) plus a sub-pixel offset "a little less than 0.5" (0.495), never stepped, so each
//   pixel's value is one formula of its own;
// - conversions with x86's float-to-int (truncation; NaN and out of range give INT_MIN, which
//   Dolphin's x86-64 build then narrows): z clamped to 24 bits, colours narrowed to 16 bits and
//   masked to 8, texture coordinates perspective-divided (q and w) and stored as s17.7 in a
//   24-bit field.
// The variant axis :coverage=console (CoverageRule::Console) changes only the coverage: the
// console's sample point and vertex precision as dolphin-emu/hwtests measured them (see
// console_subpixels); the planes, the bounding box's scissor and the clipper stay Dolphin's.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

#include "gx/clipper.h"
#include "gx/texture_lod.h"

namespace lt::gx {

// The scissor rectangle in EFB pixels, [left, right) x [top, bottom), and the scissor offset the
// screen coordinates are taken from (GX_SetScissorBoxOffset(0, 0) is the 342-pixel screen
// offset) [DHW BPFunctions.cpp ComputeScissorRects, one rectangle while nothing wraps].
struct Scissor {
  int left = 0, top = 0, right = 0, bottom = 0;
  int x_off = 342, y_off = 342;
};

// A float attribute's plane [DSW Rasterizer.cpp Slope].
struct Slope {
  float f0 = 0, dfdx = 0, dfdy = 0;
};

// The pixel the planes are measured from: vertex 0's pixel and its sub-pixel offset [DSW
// SlopeContext].
struct SlopeOrigin {
  s32 x0 = 0, y0 = 0;
  float x_off = 0, y_off = 0;
};

// x86-64's cvttss2si, which Dolphin's casts compile to: truncation toward zero, and 0x80000000
// (INT_MIN) for NaN and for anything out of the 32-bit range. Written out because the same cast
// in C++ is undefined behaviour out of range.
inline s32 x86_float_to_int(float v) {
  if (!(v >= -2147483648.0f && v < 2147483648.0f)) return INT32_MIN;
  return static_cast<s32>(v);
}

// [DSW Slope::GetValue]: f0 + dfdx * dx + dfdy * dy, dx = x_off + (float)(x - x0), left to right.
inline float slope_value(const Slope& s, const SlopeOrigin& o, s32 x, s32 y) {
  const float dx = o.x_off + static_cast<float>(x - o.x0);
  const float dy = o.y_off + static_cast<float>(y - o.y0);
  return s.f0 + (s.dfdx * dx) + (s.dfdy * dy);
}

// [DSW Draw]: "(s32)std::clamp<float>(z, 0.0f, 16777215.0f)" (a NaN passes the clamp).
inline u32 raster_depth(float z) {
  const float c = z < 0.0f ? 0.0f : (16777215.0f < z ? 16777215.0f : z);
  return static_cast<u32>(x86_float_to_int(c));
}

// [DSW Draw]: "u16 color = (u16)value; u16 mask = ~(color >> 8); tev.Color = color & mask" into
// a u8: negative values become 0, and a value just past 255 wraps (256 reads as 0, 258 as 2).
inline u8 raster_color(float v) {
  const u16 c = static_cast<u16>(x86_float_to_int(v));
  const u16 mask = static_cast<u16>(~(c >> 8));
  return static_cast<u8>(c & mask);
}

// [DSW Draw]: "tev.Uv[i].s = (s32)(pixel.Uv[i][0] * 128)" into the TEV's 24-bit signed field
// [DSW Tev.h TextureCoordinateType `signed s : 24`]: the value wraps modulo 2^24.
inline s32 raster_texcoord(float v) {
  const u32 bits = static_cast<u32>(x86_float_to_int(v * 128.0f)) << 8;
  return static_cast<s32>(bits) >> 8;
}

// A screen coordinate (pixels, with the scissor offset `offset` still in) as the rasteriser's
// 1/16-pixel integer: "iround(16.0f * (v - offset)) - 9" [DSW DrawTriangleFrontFace], where
// Dolphin's iround truncates and adds one when the fraction is at least a half, so -2.5 becomes
// -2 and 2.5 becomes 3. Pixel x then samples at 16 x, a screen position of x + 9/16.
s32 snap_to_subpixels(float screen, int offset);

// The console's sample grid: 12 * 2^15 units a pixel, the sample point 7/12 of a pixel into it.
// Why these numbers [HWT gxtest/rasterization.cpp]:
// - x: a quad's left edge at screen x = 392.58331298828125 (pixel 50 + 0.58331) covers pixel 50
//   and at the next float up, 392.58334350585938 (+ 0.58334), does not (L41-73: the viewport
//   origin 342 + xpos + 50 in float, xpos one float step either side of 0.583328247070); a
//   viewport 2e-5 pixel wide (a quad 4e-5 wide) covers pixel 0 exactly while it spans about
//   0.58333 (L75-122; L79-80: "the default subsample is located close to (but somewhat off)
//   screen position 7/12"). Dolphin read this as "pixel centers are located at 0.58333 ... each
//   pixel is divided into a 12x12 grid of subsamples" [PR#306]. 7/12 satisfies both cases when
//   the sliver's edges are taken exactly (xorig +- 2e-5 unrounded); with the float edges
//   Dolphin's viewport transform makes (which this variant keeps) one of the 515 positions of
//   L83 covers the pixel where the console did not (tests/gx_raster_test.cpp holds all of it).
// - y: not measured on hardware; 7/12 as in x is an assumption (PR#306's 12x12 grid).
// - precision: the first case moves an edge by one float step, 2^-15 pixel at x = 392, and the
//   console tells the two apart, so it holds vertices at least that finely; Dolphin's 1/16 pixel
//   cannot (both positions round onto pixel 50's sample point, which its fill rule covers). A
//   unit of 1/(12 * 2^15) pixel holds every float screen position in [256, 1024) exactly (the
//   342-pixel offset puts the whole EFB there; a float there is a multiple of 2^-15) and 7/12
//   exactly (7 * 2^15 units), so the half-space tests stay exact integers, shared with
//   Dolphin's rule (covered_span), and a vertical edge can never lie on a sample point (no float
//   is n + 7/12). Double arithmetic would hold the vertices as well, but not 7/12, and a
//   near-tie would then be decided by its rounding. A coordinate below 256 (not reached here)
//   rounds to the nearest unit.
// - ties (a sloped edge through a sample point): the hwtests do not show the rule; Dolphin's fill
//   convention is kept, so a shared edge is still drawn once.
inline constexpr int64_t kConsoleUnitsPerPixel = int64_t{12} << 15;
inline constexpr int64_t kConsoleSampleOffset = int64_t{7} << 15;  // 7/12 of a pixel

// A screen coordinate (pixels, offset still in) on the console's grid, moved by -7/12 so pixel x
// samples at kConsoleUnitsPerPixel * x, as snap_to_subpixels does for Dolphin's 1/16.
int64_t console_subpixels(float screen, int offset);

// One triangle, set up.
struct Triangle {
  s32 min_x = 0, max_x = 0, min_y = 0, max_y = 0;  // the scissored bounding box, max exclusive
  // Half-space functions e = c + dx * (y * unit) - dy * (x * unit), in units of 1/unit pixel
  // (16 under Dolphin's rule, kConsoleUnitsPerPixel under the console's); covered where all
  // three are > 0.
  std::array<int64_t, 3> c{}, dx{}, dy{};
  int64_t unit = 16;
  SlopeOrigin origin;
  Slope z, w;
  std::array<std::array<Slope, 4>, kMaxChannels> color{};
  std::array<std::array<Slope, 3>, kMaxTexGens> tex{};
  int channels = 0, texgens = 0;
};

// Sets up (v0, v1, v2) (screen positions from the clipper, wound front-facing) with `channels`
// colour channels and `texgens` texture coordinates, its coverage under `rule` (the planes are
// Dolphin's under either). Returns false when the scissored bounding box is empty (Dolphin
// returns before any slope) or a coordinate is beyond what Dolphin's 32-bit snapping holds (a
// non-finite or huge screen position: there its integers overflow; the console's rule refuses
// the same triangles).
bool setup_triangle(const RasterVertex& v0, const RasterVertex& v1, const RasterVertex& v2,
                    int channels, int texgens, const Scissor& scissor, Triangle& out,
                    CoverageRule rule = CoverageRule::Dolphin);

// The covered pixels of row y as [x_begin, x_end) (empty when x_begin >= x_end): the three
// half-space tests solved exactly in integers, which is the per-pixel test of
// DrawTriangleFrontFace (its 2x2 blocks only skip pixels no edge test would pass).
void covered_span(const Triangle& t, s32 y, s32& x_begin, s32& x_end);

// Texture coordinate g (s, t) at pixel (x, y) in float, before raster_texcoord's conversion to
// s17.7: what Dolphin's BuildBlock stores in its block's pixels [DSW BuildBlock].
std::array<float, 2> raster_texcoord_float(const Triangle& t, int g, s32 x, s32 y);
// Texture coordinate g at the three pixels of the 2x2 block holding (x, y) that Dolphin's LOD
// reads (texture_lod.h QuadTexcoords) [DSW BuildBlock, CalculateLOD].
QuadTexcoords quad_texcoords(const Triangle& t, int g, s32 x, s32 y);

// What the TEV receives at one pixel [DSW Draw, BuildBlock].
struct RasterPixel {
  u32 z = 0;
  std::array<Color8, kMaxChannels> color{};
  std::array<std::array<s32, 2>, kMaxTexGens> uv{};
};

// The values at covered pixel (x, y). `round_colors`: the shader backends' rounding of the colours
// instead of the software renderer's narrowing (the :colors=round variant). The definition: the
// pixel stage computes the same values a run of pixels at a time in vector lanes (raster_run.h),
// and tests/gx_raster_run_test.cpp holds the two together.
void raster_pixel(const Triangle& t, s32 x, s32 y, bool round_colors, RasterPixel& out);

}  // namespace lt::gx
