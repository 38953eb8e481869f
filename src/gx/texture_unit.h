// The texture unit (gx-hardware.md §3.2-3.4): textures in GX memory order (tiles), texture
// coordinates in fixed point with 7 fractional bits (truncated), 7-bit bilinear weights and the
// clamp / repeat / mirror wrap, I8 and IA8 replicated into TEXC / TEXA, RGB565 and RGBA8 (the
// colour formats a thickness map uses) decoded into TEXC = (r, g, b), TEXA = a.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gx/gx_types.h"
#include "gx/texture_lod.h"

namespace lt::gx {

// GX_InitTexObj's arguments [OGC gx.h L4272] plus the image bytes in GX tile order.
struct TextureObject {
  std::vector<u8> data;  // tile order, padded to whole tiles (tiled_size)
  int width = 0, height = 0;
  u8 format = 1;  // GX_TF_I8 1, GX_TF_IA8 3, GX_TF_RGB565 4, GX_TF_RGBA8 6 (the formats modelled)
  u8 wrap_s = 0, wrap_t = 0;  // GX_CLAMP 0, GX_REPEAT 1, GX_MIRROR 2
  bool linear = true;         // GX_LINEAR min/mag filter (GX_InitTexObj with mipmap GX_FALSE
                              // selects linear [OGC gx.c L3236-3247]); false: GX_NEAR
  // The palette of a colour-indexed format (GX_TF_CI4, CI8, CI14), as GX_LoadTlut leaves it in
  // TMEM: 2 bytes an entry in memory order, `tlut_format` GX_TL_IA8 0, RGB565 1, RGB5A3 2
  // (gx/texture_decoder.h TlutView). Empty for the other formats.
  std::vector<u8> tlut;
  u8 tlut_format = 1;
  // Where in TMEM the palette is loaded: the TLUT register's offset in 512-byte units
  // (gx/tmem.h tlut_tmem_offset), as GX_LoadTlut and GX_LoadTexObj leave it.
  u16 tlut_offset = 0;
  // Mip levels (GX_InitTexObj with mipmap GX_TRUE): `data` holds `levels` levels, level k
  // max(1, width >> k) x max(1, height >> k), each right after the whole tiles of the one before
  // (gx/texture_format.h mip_chain_bytes), as the console lays them in memory.
  int levels = 1;
  // GX_InitTexObjLOD's fields, `linear` then being the mag filter. Empty: GX_InitTexObj's
  // without mipmaps (min filter = mag filter = `linear`, LOD range 0), where no LOD changes a
  // texel; such a texture is sampled as before mipmaps were modelled.
  std::optional<TextureLod> lod;
  bool operator==(const TextureObject&) const = default;
  // Whether the pixel stage must compute a LOD for this texture (texture_lod.h lod_matters).
  bool needs_lod() const { return lod.has_value() && lod_matters(*lod, linear); }
};

inline constexpr u8 kTexFormatI8 = 1, kTexFormatIA8 = 3, kTexFormatRGB565 = 4,
                    kTexFormatRGBA8 = 6;  // GX_TF_* [OGC gx.h L291-297]
// The formats users' programs may declare today (the program reader refuses the others until it
// reads TLUTs); the sampler takes every GX_TF_* format (gx/texture_format.h).
bool is_modelled_format(u8 format);

// Bytes a format's tiles take for a width x height image, rows and columns padded to whole tiles
// (gx/texture_format.h level_bytes): I8 8x4-texel tiles of 32 bytes, IA8 and RGB565 4x4-texel
// tiles of 32 bytes, RGBA8 4x4-texel tiles of 64 bytes, and so on for every GX_TF_* format
// [OGC gx.c L3226-3300] [DHW TextureDecoder_Common.cpp block sizes].
size_t tiled_size(u8 format, int width, int height);

// Texels in row-major order to GX tile order and back. Row-major texels are, per format: I8 one
// byte; IA8 two, intensity then alpha; RGB565 the 16-bit value as two bytes, high byte first (as
// stored); RGBA8 four, r g b a. I8 texel (x, y) sits at ((y>>2)*ceil(W/8) + (x>>3))*32 + (y&3)*8 +
// (x&7). IA8 stores alpha first, then intensity, per texel; RGBA8 stores a tile's 16 (a, r) pairs
// in its first 32 bytes and its 16 (g, b) pairs in the next 32 [DHW TextureDecoder_Common.cpp
// TexDecoder_DecodeTexel].
std::vector<u8> to_tiles(u8 format, int width, int height, const std::vector<u8>& row_major);
std::vector<u8> from_tiles(u8 format, int width, int height, const std::vector<u8>& tiles);

// The filtered texel at fixed-point (u, v) (s17.7, the rasteriser's: rasteriser.h raster_texcoord):
// bilinear with 7-bit weights and truncation, or nearest (u >> 7), with each tap's index wrapped
// [DSW TextureSampler.cpp SampleMip, WrapCoord]. I8: (i, i, i, i); IA8: (i, i, i, a); RGB565: (r,
// g, b, 255) expanded to 8 bits by bit replication; RGBA8: (r, g, b, a); every other GX_TF_*
// format as gx/texture_decoder.h decodes it (colour-indexed ones through `tlut`). Every
// component is filtered on its own.
Color8 sample_texture(const TextureObject& texture, s32 u, s32 v);
// sample_texture at n pixels: out[k] is the texel at (u[k], v[k]). The texture's format, tile
// shape and checks are decoded once for all of them (the pixel stage's runs of pixels).
void sample_texture_at(const TextureObject& texture, const s32* u, const s32* v, int n,
                       Color8* out);

// The filtered texel at (u, v) for a LOD and filter quad_lod chose (texture_lod.h): level
// mip_choice(lod).level, or the blend of it and the next [DSW TextureSampler.cpp Sample]; at a
// level k the coordinate is u >> k (flooring) and the level's size max(1, size >> k) ("reduce
// sample location and texture size to mip level" [DSW SampleMip]; equal to Dolphin's
// ((size - 1) >> k) + 1 for the power-of-two sizes a mipmapped texture has). The texture's
// `lod` must be set and its levels hold every level reachable_levels names (LT_CHECK: the
// program reader and the scene refuse the rest).
void sample_texture_lod_at(const TextureObject& texture, const s32* u, const s32* v,
                           const LodChoice* lod, int n, Color8* out);

// Byte offset of level `level` in a mipmapped texture's data: the sum of the levels before it,
// each whole tiles [DSW SampleMip, "move texture pointer to mip location"].
size_t level_offset(u8 format, int width, int height, int level);

// One unfiltered texel (x, y) of a tiled texture, decoded as sample_texture reads it.
Color8 texel_at(const TextureObject& texture, int x, int y);

// RGB565's 5- and 6-bit fields to 8 bits by bit replication, (v << 3) | (v >> 2) and
// (v << 2) | (v >> 4) [DHW LookUpTables.h Convert5To8 / Convert6To8, used by
// TextureDecoder_Common.cpp DecodePixel_RGB565].
int expand5(int v);
int expand6(int v);

}  // namespace lt::gx
