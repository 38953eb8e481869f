// The texture formats of the console's texture unit (GX_TF_*), their tiles and the bytes a
// texture of each takes in memory: the facts every texture decoder, encoder, TPL file and cost
// figure shares (docs/spec/gx-hardware.md §3.4, docs/textures.md).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "gx/gx_types.h"

namespace lt::gx {

// GX_TF_* as libogc numbers them [OGC gx.h L291-301] and the texture unit's register holds them
// [HWT gxtest/BPMemory.h L19-39] (TextureFormat: I4 0 ... C14X2 0xA, CMPR 0xE).
enum class TexFormat : u8 {
  I4 = 0x0,
  I8 = 0x1,
  IA4 = 0x2,
  IA8 = 0x3,
  RGB565 = 0x4,
  RGB5A3 = 0x5,
  RGBA8 = 0x6,
  CI4 = 0x8,
  CI8 = 0x9,
  CI14X2 = 0xA,
  CMPR = 0xE,
};

// GX_TL_*: the format of a colour-indexed texture's palette entries [OGC gx.h L303-305].
enum class TlutFormat : u8 { IA8 = 0, RGB565 = 1, RGB5A3 = 2 };

inline constexpr TexFormat kAllTexFormats[] = {
    TexFormat::I4,     TexFormat::I8,     TexFormat::IA4,   TexFormat::IA8,
    TexFormat::RGB565, TexFormat::RGB5A3, TexFormat::RGBA8, TexFormat::CI4,
    TexFormat::CI8,    TexFormat::CI14X2, TexFormat::CMPR};
inline constexpr TlutFormat kAllTlutFormats[] = {TlutFormat::IA8, TlutFormat::RGB565,
                                                 TlutFormat::RGB5A3};

// One format's storage [DHW TextureDecoder_Common.cpp TexDecoder_GetBlockWidthInTexels,
// TexDecoder_GetBlockHeightInTexels, TexDecoder_GetTexelSizeInNibbles]: tiles of tile_width x
// tile_height texels stored row-major, texels row-major inside a tile; every tile is 32 bytes
// except RGBA8's, which is two 32-byte halves (AR then GB), 64 bytes. CMPR's 8x8 tile holds four
// 4x4 DXT1-like blocks of 8 bytes (top-left, top-right, bottom-left, bottom-right).
struct TexFormatInfo {
  const char* name;  // "I4" ... "CMPR" (GX_TF_ without its prefix; CI14X2 is libogc's GX_TF_CI14)
  int tile_width, tile_height;
  int bits_per_texel;  // 4, 8, 16 or 32 (CMPR: 4)
  int tile_bytes;      // 32, RGBA8 64
  int tlut_entries;    // palette entries an index can name: CI4 16, CI8 256, CI14X2 16384; else 0
};
const TexFormatInfo& format_info(TexFormat format);
bool is_indexed(TexFormat format);
const char* tlut_format_name(TlutFormat format);  // "IA8", "RGB565", "RGB5A3"

// A format by its register number (0..0xE), or by name: "I4", "i4", "GX_TF_I4"; "CI14" and
// "CI14X2" both name GX_TF_CI14. Empty when there is no such format.
std::optional<TexFormat> tex_format_from_number(int number);
std::optional<TexFormat> tex_format_from_name(std::string_view name);
std::optional<TlutFormat> tlut_format_from_name(std::string_view name);

// Bytes one level of width x height takes: whole tiles across and down. This is
// GX_GetTexBufferSize's rule [OGC gx.c L3069-3145] with each format's real tile: libogc's
// function puts CI4, CI8 and CI14 in its `default` (4x4 tiles of 32 bytes), which over-states
// CI4 and CI8 (docs/textures.md); Dolphin's block sizes are the ones the texture unit reads.
std::size_t level_bytes(TexFormat format, int width, int height);
// Bytes of a mip chain of `levels` levels from width x height down, each level half the size of
// the one before (rounded down, at least 1), stored one after another, each from a 32-byte
// boundary (every level is whole tiles): GX_GetTexBufferSize with mipmap = GX_TRUE and maxlod =
// levels [OGC gx.c L3117-3136].
std::size_t mip_chain_bytes(TexFormat format, int width, int height, int levels);
// Levels of a full chain: down to 1x1, floor(log2(max(width, height))) + 1.
int full_mip_levels(int width, int height);

}  // namespace lt::gx
