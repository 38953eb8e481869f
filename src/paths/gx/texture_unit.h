// The texture unit (gx-hardware.md §3.2-3.4): textures in GX memory order (tiles), texture
// coordinates in fixed point with 7 fractional bits (truncated), 7-bit bilinear weights and the
// clamp / repeat / mirror wrap, I8 and IA8 replicated into TEXC / TEXA.
#pragma once

#include <string>
#include <vector>

#include "paths/gx/gx_types.h"

namespace lt::gx {

// GX_InitTexObj's arguments [OGC gx.h L4272] plus the image bytes in GX tile order.
struct TextureObject {
  std::vector<u8> data;  // tile order, padded to whole tiles (tiled_size)
  int width = 0, height = 0;
  u8 format = 1;              // GX_TF_I8 1, GX_TF_IA8 3 (the formats modelled)
  u8 wrap_s = 0, wrap_t = 0;  // GX_CLAMP 0, GX_REPEAT 1, GX_MIRROR 2
  bool linear = true;         // GX_LINEAR min/mag filter (GX_InitTexObj with mipmap GX_FALSE
                              // selects linear [OGC gx.c L3236-3247]); false: GX_NEAR
  bool operator==(const TextureObject&) const = default;
};

// Bytes a format's tiles take for a width x height image: I8 8x4-texel tiles of 32 bytes, IA8
// 4x4-texel tiles of 32 bytes, rows and columns padded to whole tiles [OGC gx.c L3226-3300].
size_t tiled_size(u8 format, int width, int height);

// Texels in row-major order (I8: one byte a texel; IA8: two, intensity then alpha) to GX tile
// order and back. I8 texel (x, y) sits at ((y>>2)*ceil(W/8) + (x>>3))*32 + (y&3)*8 + (x&7).
// IA8 stores alpha first, then intensity, per texel [DHW TextureDecoder_Common.cpp].
std::vector<u8> to_tiles(u8 format, int width, int height, const std::vector<u8>& row_major);
std::vector<u8> from_tiles(u8 format, int width, int height, const std::vector<u8>& tiles);

// s (a float texture coordinate, 0..1 across the texture) to the rasteriser's fixed point:
// trunc(s * size * 128), saturated to the signed 24-bit field (s17.7) [DSW Rasterizer.cpp Draw;
// Tev.h TextureCoordinateType].
s32 to_fixed_texcoord(float s, int size);

// The filtered texel at fixed-point (u, v): bilinear with 7-bit weights and truncation, or
// nearest (u >> 7), with each tap's index wrapped [DSW TextureSampler.cpp SampleMip, WrapCoord].
// I8: (i, i, i, i); IA8: (i, i, i, a).
Color8 sample_texture(const TextureObject& texture, s32 u, s32 v);

}  // namespace lt::gx
