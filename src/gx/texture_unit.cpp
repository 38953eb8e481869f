// The texture unit (gx-hardware.md §3.2-3.4) for the formats the path uses, I8 and IA8 (the
// LUT) and RGB565 and RGBA8 (a colour thickness map): GX tile order, the s17.7 fixed-point
// coordinate and Dolphin's software sampler [DSW TextureSampler.cpp SampleMip, WrapCoord] [DHW
// TextureDecoder_Common.cpp TexDecoder_DecodeTexel].
#include "gx/texture_unit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>

#include "core/error.h"
#include "gx/texture_decoder.h"
#include "gx/texture_format.h"

namespace lt::gx {

namespace {

constexpr u8 kClamp = 0, kRepeat = 1, kMirror = 2;  // GX_CLAMP/REPEAT/MIRROR [OGC gx.h L420-422]

// Tile geometry [DHW TextureDecoder_Common.cpp TexDecoder_GetBlockWidthInTexels / Height,
// TexDecoder_GetTexelSizeInNibbles]: I8 8x4 texels of 1 byte, IA8 and RGB565 4x4 texels of 2
// bytes (32 bytes a tile); RGBA8 4x4 texels of 4 bytes, 64 bytes a tile, stored as two 32-byte
// halves of 2 bytes a texel (Dolphin: `base = tile << 5` then `offset = (base + texel) << 1`, the
// comment "shift by 5 is correct", and the second half at offset + 32).
struct TileShape {
  int width, height;
  int bytes_per_texel;  // within one 32-byte half
  int halves;           // 32-byte halves a tile: 2 for RGBA8, else 1
  // log2 of width and height: both are powers of two, and texel indices are never negative
  // (wrap() returns 0..size-1), so a shift and a mask stand for the divide and the remainder
  // (the sampler computes four offsets a pixel; a divide by a variable is slow).
  int width_shift, height_shift;
};

TileShape tile_shape(u8 format) {
  switch (format) {
    case kTexFormatI8:
      return {8, 4, 1, 1, 3, 2};
    case kTexFormatIA8:
    case kTexFormatRGB565:
      return {4, 4, 2, 1, 2, 2};
    case kTexFormatRGBA8:
      return {4, 4, 2, 2, 2, 2};
    default:
      break;
  }
  LT_CHECK(false, "texture format must be GX_TF_I8, GX_TF_IA8, GX_TF_RGB565 or GX_TF_RGBA8");
  return {};
}

// Bytes of one row-major texel (texture_unit.h): I8 1, IA8 2, RGB565 2, RGBA8 4.
int row_major_bytes(u8 format) {
  const TileShape s = tile_shape(format);
  return s.bytes_per_texel * s.halves;
}

void check_size(int width, int height) {
  // 1..1024 per side: the size registers hold width - 1 and height - 1 in 10 bits [HWT
  // gxtest/BPMemory.h L1073-1079] [OGC gx.h L4263-4264].
  LT_CHECK(width >= 1 && width <= kMaxTextureSize && height >= 1 && height <= kMaxTextureSize,
           "texture size must be 1..1024 per side");
}

int tiles_across(const TileShape& shape, int width) {
  return (width + shape.width - 1) >> shape.width_shift;
}

// Byte offset of texel (x, y)'s first byte (in the first half of an RGBA8 tile). Tiles are stored
// row-major, texels row-major inside a tile; rows of tiles are ceil(W / tile width) tiles long.
// Dolphin writes the count as ((W - 1) >> 3) + 1 for I8 and ((W - 1) >> 2) + 1 for the 4x4
// formats [DHW TexDecoder_DecodeTexel], the same number. For I8 this is
// ((y>>2)*ceil(W/8) + (x>>3))*32 + (y&3)*8 + (x&7) (§3.4).
size_t texel_offset(const TileShape& shape, int width, int x, int y) {
  const int tile =
      (y >> shape.height_shift) * tiles_across(shape, width) + (x >> shape.width_shift);
  const int in_tile = (y & (shape.height - 1)) * shape.width + (x & (shape.width - 1));
  return static_cast<size_t>(tile) * 32 * static_cast<size_t>(shape.halves) +
         static_cast<size_t>(in_tile * shape.bytes_per_texel);
}

// One level of a texture: level 0, or one of its mip levels (the tiles right after the levels
// before it). `texture` gives the format, the wraps and the palette.
struct LevelView {
  const TextureObject* texture = nullptr;
  const u8* data = nullptr;
  size_t bytes = 0;
  int width = 0, height = 0;
};

LevelView level_view(const TextureObject& texture, int level);

// One texel, decoded [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel]:
// - I8 replicates its one byte into every component.
// - IA8 stores alpha in the first byte and intensity in the second: Dolphin reads the two bytes
//   as a little-endian u16 and takes `a = val & 0xFF` (first byte), `i = val >> 8` (second)
//   [DecodePixel_IA8]; the same order as RGBA8's AR half (A at the lower address).
// - RGB565 is a big-endian u16 (Dolphin byte-swaps it, `Common::swap16(val)`), r in bits 15..11,
//   g 10..5, b 4..0, each expanded by bit replication; alpha 255 [DecodePixel_RGB565].
// - RGBA8: a = byte 0, r = byte 1 of the texel's pair in the first half, g = byte 0 and b = byte
//   1 of its pair in the second half (offset + 32).
// Always inlined: the bilinear sampler calls it four times a pixel.
// Texel (x, y) of a level of format Format (tile_shape has refused the formats not modelled).
template <u8 Format>
[[gnu::always_inline]] inline Color8 fetch(const LevelView& tex, const TileShape& shape, int x,
                                           int y) {
  const size_t o = texel_offset(shape, tex.width, x, y);
  const u8* d = tex.data;
  if constexpr (Format == kTexFormatI8) {
    return {d[o], d[o], d[o], d[o]};
  } else if constexpr (Format == kTexFormatIA8) {
    return {d[o + 1], d[o + 1], d[o + 1], d[o]};
  } else if constexpr (Format == kTexFormatRGB565) {
    const int v = (d[o] << 8) | d[o + 1];
    return {static_cast<u8>(expand5((v >> 11) & 0x1f)), static_cast<u8>(expand6((v >> 5) & 0x3f)),
            static_cast<u8>(expand5(v & 0x1f)), 255};
  } else {
    static_assert(Format == kTexFormatRGBA8);
    return {d[o + 1], d[o + 32], d[o + 33], d[o]};
  }
}

// Every other format: the decoder's texel (gx/texture_decoder.h), TLUT included. The four above
// are its rules inlined for the pixel stage's speed (GxTextureDecoder.TheFourFormatsOfTodays-
// TextureUnitDecodeByteIdentically holds them to it).
constexpr u8 kAnyFormat = 0xff;
template <>
[[gnu::always_inline]] inline Color8 fetch<kAnyFormat>(const LevelView& level, const TileShape&,
                                                       int x, int y) {
  const TextureObject& tex = *level.texture;
  const TextureView view{static_cast<TexFormat>(tex.format), level.width, level.height,
                         std::span<const u8>(level.data, level.bytes)};
  const TlutView tlut{static_cast<TlutFormat>(tex.tlut_format), tex.tlut};
  return decode_texel(view, x, y, &tlut);
}

// The tile shape of the four inlined formats; the decoder finds every other format's itself.
TileShape shape_for_sampling(u8 format) {
  return is_modelled_format(format) ? tile_shape(format) : TileShape{};
}

// A tap's index wrapped by `mode` (checked by the caller: check_texture).
[[gnu::always_inline]] inline std::int64_t wrap(std::int64_t i, u8 mode, int size) {
  if (mode == kRepeat) return i & (size - 1);
  if (mode == kMirror) {
    // An odd repeat (bit `size` set) is reflected: ~i = -1 - i, so for a power-of-two size
    // i = size..2*size-1 maps to 2*size-1-i and i = -1..-size to 0..size-1.
    if ((i & size) != 0) i = ~i;
    return i & (size - 1);
  }
  return std::clamp<std::int64_t>(i, 0, size - 1);
}

}  // namespace

bool is_modelled_format(u8 format) {
  return format == kTexFormatI8 || format == kTexFormatIA8 || format == kTexFormatRGB565 ||
         format == kTexFormatRGBA8;
}

int expand5(int v) {
  return (v << 3) | (v >> 2);
}
int expand6(int v) {
  return (v << 2) | (v >> 4);
}

size_t tiled_size(u8 format, int width, int height) {
  const std::optional<TexFormat> f = tex_format_from_number(format);
  LT_CHECK(f.has_value(), "texture format must be a GX_TF_* format");
  check_size(width, height);
  return level_bytes(*f, width, height);
}

namespace {

// Where the k-th byte of a row-major texel lives relative to the texel's offset in the tiles:
// the inverse of fetch's reading order.
size_t tile_byte(u8 format, int k) {
  switch (format) {
    case kTexFormatIA8:  // row-major (i, a) -> tile (a, i)
      return k == 0 ? 1 : 0;
    case kTexFormatRGBA8: {  // row-major (r, g, b, a) -> (a, r) at +0, (g, b) at +32
      constexpr size_t where[4] = {1, 32, 33, 0};
      return where[k];
    }
    default:  // I8, and RGB565 whose two bytes are stored as given (high byte first)
      return static_cast<size_t>(k);
  }
}

}  // namespace

std::vector<u8> to_tiles(u8 format, int width, int height, const std::vector<u8>& row_major) {
  const TileShape shape = tile_shape(format);
  const int bytes = row_major_bytes(format);
  std::vector<u8> tiles(tiled_size(format, width, height), 0);  // padding texels are zero
  LT_CHECK(row_major.size() == static_cast<size_t>(width) * static_cast<size_t>(height) *
                                   static_cast<size_t>(bytes),
           "row-major texel data has the wrong size");
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t src = (static_cast<size_t>(y) * width + x) * static_cast<size_t>(bytes);
      const size_t dst = texel_offset(shape, width, x, y);
      for (int k = 0; k < bytes; ++k) tiles[dst + tile_byte(format, k)] = row_major[src + k];
    }
  }
  return tiles;
}

std::vector<u8> from_tiles(u8 format, int width, int height, const std::vector<u8>& tiles) {
  const TileShape shape = tile_shape(format);
  const int bytes = row_major_bytes(format);
  LT_CHECK(tiles.size() == tiled_size(format, width, height), "tile data has the wrong size");
  std::vector<u8> row_major(static_cast<size_t>(width) * static_cast<size_t>(height) *
                            static_cast<size_t>(bytes));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t dst = (static_cast<size_t>(y) * width + x) * static_cast<size_t>(bytes);
      const size_t src = texel_offset(shape, width, x, y);
      for (int k = 0; k < bytes; ++k) row_major[dst + k] = tiles[src + tile_byte(format, k)];
    }
  }
  return row_major;
}

namespace {

// Bytes of every level of `texture`.
size_t data_bytes(const TextureObject& texture) {
  const std::optional<TexFormat> f = tex_format_from_number(texture.format);
  LT_CHECK(f.has_value(), "texture format must be a GX_TF_* format");
  check_size(texture.width, texture.height);
  return mip_chain_bytes(*f, texture.width, texture.height, texture.levels);
}

// What every sample of a texture relies on, checked once per call of sample_texture_at rather
// than per texel.
void check_texture(const TextureObject& texture) {
  LT_CHECK(texture.data.size() == data_bytes(texture),
           "texture data must hold the whole tiles of its size and levels");
  for (u8 mode : {texture.wrap_s, texture.wrap_t})
    LT_CHECK(mode == kClamp || mode == kRepeat || mode == kMirror || mode == 3,
             "wrap mode must be GX_CLAMP, GX_REPEAT, GX_MIRROR (or 3)");
}

LevelView level_view(const TextureObject& texture, int level) {
  LevelView view;
  view.texture = &texture;
  view.width = std::max(1, texture.width >> level);
  view.height = std::max(1, texture.height >> level);
  const size_t offset = level_offset(texture.format, texture.width, texture.height, level);
  view.data = texture.data.data() + offset;
  view.bytes = texture.data.size() - offset;
  return view;
}

// One texture's format, picked once for a run of pixels.
template <class Body>
void with_format(u8 format, Body&& body) {
  switch (format) {
    case kTexFormatI8:
      return body(std::integral_constant<u8, kTexFormatI8>{});
    case kTexFormatIA8:
      return body(std::integral_constant<u8, kTexFormatIA8>{});
    case kTexFormatRGB565:
      return body(std::integral_constant<u8, kTexFormatRGB565>{});
    case kTexFormatRGBA8:
      return body(std::integral_constant<u8, kTexFormatRGBA8>{});
    default:  // every other GX_TF_* format (check_texture refused the rest)
      return body(std::integral_constant<u8, kAnyFormat>{});
  }
}

template <u8 Format>
Color8 sample_one(const LevelView& level, const TileShape& shape, bool linear, s32 u, s32 v) {
  const TextureObject& texture = *level.texture;
  const int w = level.width, h = level.height;
  if (!linear) {
    // Nearest: the texel containing (u, v), u >> 7 (flooring) [DSW SampleMip].
    const int x = static_cast<int>(wrap(std::int64_t{u} >> 7, texture.wrap_s, w));
    const int y = static_cast<int>(wrap(std::int64_t{v} >> 7, texture.wrap_t, h));
    return fetch<Format>(level, shape, x, y);
  }
  // Bilinear [DSW SampleMip]: the -64 (half a texel) moves the sample to texel centres; the
  // arithmetic shift floors negative coordinates; 7-bit weights, products summed in 14
  // fractional bits and truncated, each component on its own (I8's replicated intensity gives
  // the same value in every component).
  const std::int64_t us = std::int64_t{u} - 64, vs = std::int64_t{v} - 64;
  const int fs = static_cast<int>(us & 127), ft = static_cast<int>(vs & 127);
  const int x0 = static_cast<int>(wrap(us >> 7, texture.wrap_s, w));
  const int x1 = static_cast<int>(wrap((us >> 7) + 1, texture.wrap_s, w));
  const int y0 = static_cast<int>(wrap(vs >> 7, texture.wrap_t, h));
  const int y1 = static_cast<int>(wrap((vs >> 7) + 1, texture.wrap_t, h));
  const Color8 t00 = fetch<Format>(level, shape, x0, y0);
  const Color8 t10 = fetch<Format>(level, shape, x1, y0);
  const Color8 t01 = fetch<Format>(level, shape, x0, y1);
  const Color8 t11 = fetch<Format>(level, shape, x1, y1);
  const int w00 = (128 - fs) * (128 - ft), w10 = fs * (128 - ft);
  const int w01 = (128 - fs) * ft, w11 = fs * ft;
  Color8 out;
  for (int c = 0; c < 4; ++c)
    out[c] = static_cast<u8>((t00[c] * w00 + t10[c] * w10 + t01[c] * w01 + t11[c] * w11) >> 14);
  return out;
}

// [DSW TextureSampler.cpp Sample, SampleMip]: the level(s) the LOD picks, the coordinate shifted
// down to the level ("s >>= mip", an arithmetic shift), and a linear mip filter's blend of two
// levels, (16 - f) and f sixteenths of each component, summed and shifted down by 4.
template <u8 Format>
Color8 sample_lod(const std::vector<LevelView>& levels, const TileShape& shape,
                  const TextureLod& mode, LodChoice choice, s32 u, s32 v) {
  const MipChoice mip = mip_choice(mode, choice.lod);
  const auto at = [&](int level) {
    LT_CHECK(level < static_cast<int>(levels.size()), "a LOD past the texture's levels");
    return sample_one<Format>(levels[static_cast<size_t>(level)], shape, choice.linear, u >> level,
                              v >> level);
  };
  const Color8 base = at(mip.level);
  if (mip.fraction == 0) return base;
  const Color8 next = at(mip.level + 1);
  Color8 out;
  for (int c = 0; c < 4; ++c)
    out[c] = static_cast<u8>((base[c] * (16 - mip.fraction) + next[c] * mip.fraction) >> 4);
  return out;
}

}  // namespace

size_t level_offset(u8 format, int width, int height, int level) {
  if (level == 0) return 0;
  const std::optional<TexFormat> f = tex_format_from_number(format);
  LT_CHECK(f.has_value(), "texture format must be a GX_TF_* format");
  return mip_chain_bytes(*f, width, height, level);
}

Color8 texel_at(const TextureObject& texture, int x, int y) {
  LT_CHECK(x >= 0 && x < texture.width && y >= 0 && y < texture.height, "texel out of range");
  LT_CHECK(texture.data.size() == data_bytes(texture),
           "texture data must hold the whole tiles of its size and levels");
  const TileShape shape = shape_for_sampling(texture.format);
  const LevelView level = level_view(texture, 0);
  Color8 out;
  with_format(texture.format,
              [&](auto format) { out = fetch<decltype(format)::value>(level, shape, x, y); });
  return out;
}

void sample_texture_at(const TextureObject& texture, const s32* u, const s32* v, int n,
                       Color8* out) {
  const TileShape shape = shape_for_sampling(texture.format);
  check_texture(texture);
  const LevelView level = level_view(texture, 0);
  with_format(texture.format, [&](auto format) {
    for (int k = 0; k < n; ++k)
      out[k] = sample_one<decltype(format)::value>(level, shape, texture.linear, u[k], v[k]);
  });
}

void sample_texture_lod_at(const TextureObject& texture, const s32* u, const s32* v,
                           const LodChoice* lod, int n, Color8* out) {
  LT_CHECK(texture.lod.has_value(), "sampling by LOD needs the texture's LOD fields");
  const TileShape shape = shape_for_sampling(texture.format);
  check_texture(texture);
  std::vector<LevelView> levels;
  for (int k = 0; k < texture.levels; ++k) levels.push_back(level_view(texture, k));
  with_format(texture.format, [&](auto format) {
    for (int k = 0; k < n; ++k)
      out[k] = sample_lod<decltype(format)::value>(levels, shape, *texture.lod, lod[k], u[k], v[k]);
  });
}

Color8 sample_texture(const TextureObject& texture, s32 u, s32 v) {
  Color8 out;
  sample_texture_at(texture, &u, &v, 1, &out);
  return out;
}

}  // namespace lt::gx
