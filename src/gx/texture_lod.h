// The texture unit's level of detail (gx-hardware.md §3.5): the LOD fields of a texture map's
// TX_SETMODE0 / TX_SETMODE1 registers as GX_InitTexObjLOD writes them, the LOD of a 2x2 quad of
// pixels from its texture-coordinate deltas, and the mip level(s) a LOD selects, all in the
// fixed-point form of Dolphin's software renderer [DSW Rasterizer.cpp CalculateLOD, FixedLog2]
// [DSW TextureSampler.cpp Sample].
#pragma once

#include <cstdint>

#include "gx/gx_types.h"

namespace lt::gx {

// GX_InitTexObjLOD's fields as the registers hold them [OGC gx.c GX_InitTexObjLOD L3310-3334]
// [DHW BPMemory.h TexMode0, TexMode1]. The mag filter is TextureObject::linear.
struct TextureLod {
  // TexMode0 bits 5-7, libogc's GX_NEAR .. GX_LIN_MIP_LIN through _gx2HWFiltConv [OGC gx.c
  // L108]: 0 GX_NEAR, 4 GX_LINEAR, 1 NEAR_MIP_NEAR, 5 LIN_MIP_NEAR, 2 NEAR_MIP_LIN, 6 LIN_MIP_LIN.
  // Bit 2 is the filter inside a level, bits 0-1 the mip filter (0 none, 1 point, 2 linear;
  // Dolphin's MipMode, which reads 3 as "some mip filter", neither point nor linear).
  u8 min_filter = 4;
  std::int8_t bias = 0;         // bits 9-16: s2.5, (u32)(32 * lodbias) masked to 8 bits
  bool diagonal = false;        // bit 8: GX_InitTexObjLOD's !edgelod (0 "edge" LOD, 1 "diagonal")
  bool bias_clamp = false;      // bit 21, read by nothing in Dolphin's software renderer
  u8 max_aniso = 0;             // bits 19-20, likewise
  u8 min_lod = 0, max_lod = 0;  // TexMode1 bits 0-7 and 8-15: u4.4 (16 * lod), 0..160
  bool operator==(const TextureLod&) const = default;

  int mip_filter() const { return min_filter & 3; }
  bool min_linear() const { return (min_filter & 4) != 0; }
};

// The fields libogc's GX_InitTexObjLOD(obj, minfilt, magfilt, minlod, maxlod, lodbias,
// biasclamp, edgelod, maxaniso) writes [OGC gx.c L3310-3334]: the min filter through
// _gx2HWFiltConv [L108]; the bias clamped to -4 (and 4.0 taken as 3.99), then (u32)(32 * bias)
// masked to 8 bits (a negative bias truncates toward zero and wraps, as the console's conversion
// through a signed integer gives); min and max LOD clamped to 0..10 and (u32)(16 * lod).
// `minfilt` is GX_NEAR 0 .. GX_LIN_MIP_LIN 5.
TextureLod libogc_texture_lod(int minfilt, float minlod, float maxlod, float lodbias,
                              bool biasclamp, bool edgelod, int maxaniso);
// GX_InitTexObj's LOD fields with mipmap GX_TRUE [OGC gx.c L3236-3247]: min filter
// GX_LIN_MIP_LIN (6), or GX_LIN_MIP_NEAR (5) for a colour-indexed format; everything else 0 (so
// max LOD 0: level 0 until GX_InitTexObjLOD sets a range).
TextureLod mipmapped_texture_lod(bool indexed);

// An approximation of log2(f) in s28.4 [DSW Rasterizer.cpp FixedLog2]: the float's biased
// exponent times 16, minus 127 * 16, plus the top four bits of its mantissa (linear between
// powers of two). The sign bit is ignored (the deltas are absolute values).
s32 fixed_log2(float f);

// The float texture coordinates (in texels of level 0, before the s17.7 conversion) of a quad's
// pixels (x, y), (x + 1, y) and (x, y + 1), x and y even: Dolphin computes the LOD once per 2x2
// block of its rasteriser from these three [DSW Rasterizer.cpp BuildBlock, CalculateLOD].
struct QuadTexcoords {
  float u00 = 0, v00 = 0, u10 = 0, v10 = 0, u01 = 0, v01 = 0;
};

// What CalculateLOD leaves for the sampler: the LOD in s28.4, clamped to the texture's range,
// and whether the level(s) are filtered bilinearly.
struct LodChoice {
  s32 lod = 0;
  bool linear = true;
};

// [DSW Rasterizer.cpp CalculateLOD]: du/dx, dv/dx, du/dy, dv/dy as absolute differences; edge
// LOD takes max(du/dx, du/dy) and max(dv/dx, dv/dy), diagonal LOD their sums; the LOD is
// fixed_log2 of the larger, plus the bias >> 1 (s2.5 to s.4, an arithmetic shift). Linear when
// the LOD is above 0 and the min filter is linear, or at or below 0 and the mag filter is; the
// filter is chosen before the clamp, then the LOD is clamped: above max_lod to it, else below
// min_lod to it (in that order, so min_lod > max_lod gives max_lod to every LOD above it).
LodChoice quad_lod(const TextureLod& mode, bool mag_linear, const QuadTexcoords& q);

// The level(s) a LOD samples [DSW TextureSampler.cpp Sample]: with a mip filter and LOD > 0,
// level lod >> 4; a point mip filter rounds up when the fraction lod & 15 is 8 or more, a linear
// one blends level and level + 1 by the fraction (16 - f and f sixteenths, summed and shifted
// down by 4, truncating); otherwise level 0.
struct MipChoice {
  int level = 0;
  int fraction = 0;  // 1..15 blends with level + 1; 0 reads `level` alone
};
MipChoice mip_choice(const TextureLod& mode, s32 lod);

// Levels the sampler may read under `mode`, whatever the LOD: 1 without a mip filter; else the
// level of the largest LOD the clamp lets through, max(min_lod, max_lod), plus the next one when
// its fraction is not 0 (blended, or rounded up to).
int reachable_levels(const TextureLod& mode);

// Whether a texture's LOD can change what it samples: the min filter differs from the mag
// filter, or a mip filter with a LOD range above 0. Otherwise every pixel samples level 0 with
// the mag filter, and the LOD need not be computed (the frames of textures without mipmaps).
bool lod_matters(const TextureLod& mode, bool mag_linear);

}  // namespace lt::gx
