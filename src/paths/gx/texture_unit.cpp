// The texture unit (gx-hardware.md §3.2-3.4) for the formats the path uses, I8 and IA8: GX tile
// order, the s17.7 fixed-point coordinate and Dolphin's software sampler [DSW TextureSampler.cpp
// SampleMip, WrapCoord] [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel].
#include "paths/gx/texture_unit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "core/error.h"

namespace lt::gx {

namespace {

constexpr u8 kFormatI8 = 1, kFormatIA8 = 3;         // GX_TF_I8, GX_TF_IA8 [OGC gx.h L292-294]
constexpr u8 kClamp = 0, kRepeat = 1, kMirror = 2;  // GX_CLAMP/REPEAT/MIRROR [OGC gx.h L420-422]

// Tile geometry [DHW TextureDecoder_Common.cpp TexDecoder_GetBlockWidthInTexels / Height]:
// I8 8x4 texels of 1 byte, IA8 4x4 texels of 2 bytes; both 32 bytes a tile.
struct TileShape {
  int width, height, bytes_per_texel;
};

TileShape tile_shape(u8 format) {
  if (format == kFormatI8) return {8, 4, 1};
  LT_CHECK(format == kFormatIA8, "texture format must be GX_TF_I8 or GX_TF_IA8");
  return {4, 4, 2};
}

void check_size(int width, int height) {
  // 1..1024 per side: the size registers hold width - 1 and height - 1 in 10 bits [HWT
  // gxtest/BPMemory.h L1073-1079] [OGC gx.h L4263-4264].
  LT_CHECK(width >= 1 && width <= kMaxTextureSize && height >= 1 && height <= kMaxTextureSize,
           "texture size must be 1..1024 per side");
}

int tiles_across(const TileShape& shape, int width) {
  return (width + shape.width - 1) / shape.width;
}

// Byte offset of texel (x, y)'s first byte. Tiles are stored row-major, texels row-major
// inside a tile; rows of tiles are ceil(W / tile width) tiles long. Dolphin writes the count as
// ((W - 1) >> 3) + 1 for I8 and ((W - 1) >> 2) + 1 for IA8 [DHW TexDecoder_DecodeTexel], the
// same number. For I8 this is ((y>>2)*ceil(W/8) + (x>>3))*32 + (y&3)*8 + (x&7) (§3.4).
size_t texel_offset(const TileShape& shape, int width, int x, int y) {
  const int tile = (y / shape.height) * tiles_across(shape, width) + x / shape.width;
  const int in_tile = (y % shape.height) * shape.width + x % shape.width;
  return static_cast<size_t>(tile) * 32 + static_cast<size_t>(in_tile * shape.bytes_per_texel);
}

// One texel as (intensity, alpha). IA8 stores alpha in the first byte and intensity in the
// second: Dolphin reads the two bytes as a little-endian u16 and takes `a = val & 0xFF` (first
// byte), `i = val >> 8` (second) [DHW TextureDecoder_Common.cpp DecodePixel_IA8,
// TexDecoder_DecodeTexel case IA8]; the same order as RGBA8's AR half (A at the lower address).
// I8 replicates its one byte into every component [same file, case I8].
struct Texel {
  int intensity, alpha;
};

Texel fetch(const TextureObject& tex, const TileShape& shape, int x, int y) {
  const size_t offset = texel_offset(shape, tex.width, x, y);
  if (tex.format == kFormatI8) return {tex.data[offset], tex.data[offset]};
  return {tex.data[offset + 1], tex.data[offset]};
}

// An integer texel index wrapped into [0, size) [DSW TextureSampler.cpp WrapCoord]. REPEAT and
// MIRROR use size - 1 as a mask, which assumes a power-of-two size (YAGCD, quoted there); with
// another size they still land in range, just not evenly. Mode 3 behaves as CLAMP ("hardware
// testing indicates", same function). int64 because u - 64 of an arbitrary s32 may not fit.
std::int64_t wrap(std::int64_t i, u8 mode, int size) {
  LT_CHECK(mode == kClamp || mode == kRepeat || mode == kMirror || mode == 3,
           "wrap mode must be GX_CLAMP, GX_REPEAT, GX_MIRROR (or 3)");
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

size_t tiled_size(u8 format, int width, int height) {
  const TileShape shape = tile_shape(format);
  check_size(width, height);
  const int rows = (height + shape.height - 1) / shape.height;
  return static_cast<size_t>(tiles_across(shape, width)) * static_cast<size_t>(rows) * 32;
}

std::vector<u8> to_tiles(u8 format, int width, int height, const std::vector<u8>& row_major) {
  const TileShape shape = tile_shape(format);
  std::vector<u8> tiles(tiled_size(format, width, height), 0);  // padding texels are zero
  LT_CHECK(row_major.size() == static_cast<size_t>(width) * static_cast<size_t>(height) *
                                   static_cast<size_t>(shape.bytes_per_texel),
           "row-major texel data has the wrong size");
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t src = (static_cast<size_t>(y) * width + x) * shape.bytes_per_texel;
      const size_t dst = texel_offset(shape, width, x, y);
      if (format == kFormatI8) {
        tiles[dst] = row_major[src];
      } else {  // row-major (intensity, alpha) -> tile (alpha, intensity)
        tiles[dst] = row_major[src + 1];
        tiles[dst + 1] = row_major[src];
      }
    }
  }
  return tiles;
}

std::vector<u8> from_tiles(u8 format, int width, int height, const std::vector<u8>& tiles) {
  const TileShape shape = tile_shape(format);
  LT_CHECK(tiles.size() == tiled_size(format, width, height), "tile data has the wrong size");
  std::vector<u8> row_major(static_cast<size_t>(width) * static_cast<size_t>(height) *
                            static_cast<size_t>(shape.bytes_per_texel));
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const size_t dst = (static_cast<size_t>(y) * width + x) * shape.bytes_per_texel;
      const size_t src = texel_offset(shape, width, x, y);
      if (format == kFormatI8) {
        row_major[dst] = tiles[src];
      } else {
        row_major[dst] = tiles[src + 1];
        row_major[dst + 1] = tiles[src];
      }
    }
  }
  return row_major;
}

s32 to_fixed_texcoord(float s, int size) {
  // Float, as both Dolphin paths: the XF output is scaled by the texture size in float [DSW
  // TransformUnit.cpp TransformTexCoord, `*= scale_minus_1 + 1`] and the rasteriser converts
  // with (s32)(uv * 128) [DSW Rasterizer.cpp Draw, "TEV stores UVs as s17.7"]; the shader path
  // computes int(uv * (size * 128)) [DHW PixelShaderGen `fixpoint_uv`, PR#2075]. The * 128 is
  // exact in float, so both equal trunc(fl(s * size) * 128).
  const float scaled = s * static_cast<float>(size) * 128.0f;
  // The field is 24-bit signed [DSW Tev.h TextureCoordinateType `s : 24`]. Dolphin wraps an
  // out-of-range value (bit-field store; its shader says "TODO: S24 overflows here?"); no
  // hardware test says what the console does. Saturation is this path's choice: it keeps huge
  // coordinates on the texture's edge texel under CLAMP and makes float-to-int defined. NaN has
  // no coordinate: 0.
  constexpr float kMax = 8388607.0f, kMin = -8388608.0f;  // 2^23 - 1 and -2^23, exact in float
  if (std::isnan(scaled)) return 0;
  if (scaled >= kMax) return 8388607;
  if (scaled <= kMin) return -8388608;
  return static_cast<s32>(scaled);  // truncation toward zero, as (s32) in DSW
}

Color8 sample_texture(const TextureObject& texture, s32 u, s32 v) {
  const TileShape shape = tile_shape(texture.format);
  LT_CHECK(texture.data.size() == tiled_size(texture.format, texture.width, texture.height),
           "texture data must hold the whole tiles of its size");
  const int w = texture.width, h = texture.height;
  Texel result{};
  if (texture.linear) {
    // Bilinear [DSW SampleMip]: the -64 (half a texel) moves the sample to texel centres; the
    // arithmetic shift floors negative coordinates; 7-bit weights, products summed in 14
    // fractional bits and truncated.
    const std::int64_t us = std::int64_t{u} - 64, vs = std::int64_t{v} - 64;
    const int fs = static_cast<int>(us & 127), ft = static_cast<int>(vs & 127);
    const int x0 = static_cast<int>(wrap(us >> 7, texture.wrap_s, w));
    const int x1 = static_cast<int>(wrap((us >> 7) + 1, texture.wrap_s, w));
    const int y0 = static_cast<int>(wrap(vs >> 7, texture.wrap_t, h));
    const int y1 = static_cast<int>(wrap((vs >> 7) + 1, texture.wrap_t, h));
    const Texel t00 = fetch(texture, shape, x0, y0), t10 = fetch(texture, shape, x1, y0);
    const Texel t01 = fetch(texture, shape, x0, y1), t11 = fetch(texture, shape, x1, y1);
    const int w00 = (128 - fs) * (128 - ft), w10 = fs * (128 - ft);
    const int w01 = (128 - fs) * ft, w11 = fs * ft;
    result.intensity =
        (t00.intensity * w00 + t10.intensity * w10 + t01.intensity * w01 + t11.intensity * w11) >>
        14;
    result.alpha = (t00.alpha * w00 + t10.alpha * w10 + t01.alpha * w01 + t11.alpha * w11) >> 14;
  } else {
    // Nearest: the texel containing (u, v), u >> 7 (flooring) [DSW SampleMip].
    const int x = static_cast<int>(wrap(std::int64_t{u} >> 7, texture.wrap_s, w));
    const int y = static_cast<int>(wrap(std::int64_t{v} >> 7, texture.wrap_t, h));
    result = fetch(texture, shape, x, y);
  }
  // TEXC = (i, i, i), TEXA = i for I8 and a for IA8 (fetch already gave I8 alpha = i).
  const u8 i = static_cast<u8>(result.intensity), a = static_cast<u8>(result.alpha);
  return Color8{i, i, i, a};
}

}  // namespace lt::gx
