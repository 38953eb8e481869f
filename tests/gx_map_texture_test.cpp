// The gx texture unit's colour formats and the thickness map's texture (GX_TEXMAP1):
// GX_TF_RGB565 and GX_TF_RGBA8 tile order and decode against hand-made bytes, the 7-bit bilinear
// filter on them against fixed-point values worked out by hand, and the quantisation and
// orientation of paths/gx/thickness_texture.h. Byte offsets and expansions follow the formulas
// cited in texture_unit.h (Dolphin's TexDecoder_DecodeTexel, Convert5To8 / Convert6To8).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "gx/rasteriser.h"
#include "gx/texture_encoder.h"
#include "gx/texture_unit.h"
#include "paths/gx/thickness_texture.h"

namespace lt::gx {
namespace {

// ---- RGB565: 4x4 tiles of 32 bytes, texels big-endian u16 ----

TEST(GxMapTexture, Rgb565TileOrderIsBigEndianIn4x4Tiles) {
  // 6 x 5 texels, v(x, y) = (x+1) << 11 | (y+1) << 5 | (x+y): every field tells where it was.
  auto value = [](int x, int y) { return ((x + 1) << 11) | ((y + 1) << 5) | (x + y); };
  std::vector<u8> rows;
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 6; ++x) {
      rows.push_back(static_cast<u8>(value(x, y) >> 8));
      rows.push_back(static_cast<u8>(value(x, y) & 0xff));
    }
  }
  // ceil(6/4) = 2 tiles across, ceil(5/4) = 2 down, 32 bytes each.
  ASSERT_EQ(tiled_size(kTexFormatRGB565, 6, 5), 128u);
  const std::vector<u8> tiles = to_tiles(kTexFormatRGB565, 6, 5, rows);
  // Offset ((y>>2)*2 + (x>>2))*32 + ((y&3)*4 + (x&3))*2, high byte first.
  EXPECT_EQ(tiles[0], 0x08);  // (0, 0) = 0x0820
  EXPECT_EQ(tiles[1], 0x20);
  EXPECT_EQ(tiles[12], 0x18);  // (2, 1) = 3<<11 | 2<<5 | 3 = 0x1843, at (4 + 2) * 2
  EXPECT_EQ(tiles[13], 0x43);
  EXPECT_EQ(tiles[32], 0x28);  // (4, 0) = 0x2824: the second tile
  EXPECT_EQ(tiles[33], 0x24);
  EXPECT_EQ(tiles[98], 0x30);  // (5, 4) = 6<<11 | 5<<5 | 9 = 0x30A9, at 3*32 + 2
  EXPECT_EQ(tiles[99], 0xA9);
  EXPECT_EQ(tiles[36], 0);  // (6, 0): padding
  EXPECT_EQ(from_tiles(kTexFormatRGB565, 6, 5, tiles), rows);
  // (5, 4) decoded: r = 6 -> 6<<3 | 6>>2 = 49, g = 5 -> 5<<2 | 5>>4 = 20, b = 9 -> 72 | 2 = 74.
  TextureObject t;
  t.format = kTexFormatRGB565;
  t.width = 6;
  t.height = 5;
  t.data = tiles;
  EXPECT_EQ(texel_at(t, 5, 4), (Color8{49, 20, 74, 255}));
}

TEST(GxMapTexture, Rgb565DecodesHandMadeBytesByBitReplication) {
  TextureObject t;
  t.format = kTexFormatRGB565;
  t.width = t.height = 4;
  t.data.assign(32, 0);
  t.data[0] = 0xF8;  // (0, 0) = 0xF800: red only
  t.data[2] = 0x07;  // (1, 0) = 0x07E0: green only
  t.data[3] = 0xE0;
  t.data[5] = 0x1F;   // (2, 0) = 0x001F: blue only
  t.data[22] = 0x84;  // (3, 2): texel 2*4 + 3 = 11, bytes 22, 23 = 0x8410: r = 16, g = 32, b = 16
  t.data[23] = 0x10;
  EXPECT_EQ(texel_at(t, 0, 0), (Color8{255, 0, 0, 255}));
  EXPECT_EQ(texel_at(t, 1, 0), (Color8{0, 255, 0, 255}));
  EXPECT_EQ(texel_at(t, 2, 0), (Color8{0, 0, 255, 255}));
  // 16 -> 128 | 4 = 132; 32 -> 128 | 2 = 130.
  EXPECT_EQ(texel_at(t, 3, 2), (Color8{132, 130, 132, 255}));
  EXPECT_EQ(texel_at(t, 3, 3), (Color8{0, 0, 0, 255}));
}

// ---- RGBA8: 4x4 tiles of 64 bytes, (a, r) pairs then (g, b) pairs ----

TEST(GxMapTexture, Rgba8TileOrderSplitsArAndGbHalves) {
  // 5 x 5 texels, k = x + 5y: (r, g, b, a) = (k, 100 + k, 150 + k, 30 + k).
  std::vector<u8> rows;
  for (int k = 0; k < 25; ++k) {
    for (int v : {k, 100 + k, 150 + k, 30 + k}) rows.push_back(static_cast<u8>(v));
  }
  ASSERT_EQ(tiled_size(kTexFormatRGBA8, 5, 5), 256u);  // 2 x 2 tiles of 64 bytes
  const std::vector<u8> tiles = to_tiles(kTexFormatRGBA8, 5, 5, rows);
  // Texel (x, y): tile ((y>>2)*2 + (x>>2)) * 64 + ((y&3)*4 + (x&3)) * 2 holds (a, r); 32 bytes
  // further, (g, b).
  EXPECT_EQ(tiles[0], 30);  // (0, 0)
  EXPECT_EQ(tiles[1], 0);
  EXPECT_EQ(tiles[32], 100);
  EXPECT_EQ(tiles[33], 150);
  EXPECT_EQ(tiles[18], 41);  // (1, 2): k = 11, texel 9 of tile 0
  EXPECT_EQ(tiles[19], 11);
  EXPECT_EQ(tiles[50], 111);
  EXPECT_EQ(tiles[51], 161);
  EXPECT_EQ(tiles[30], 48);  // (3, 3): k = 18, texel 15, the last pair of each half
  EXPECT_EQ(tiles[31], 18);
  EXPECT_EQ(tiles[62], 118);
  EXPECT_EQ(tiles[63], 168);
  EXPECT_EQ(tiles[64], 34);  // (4, 0): k = 4, the second tile starts at 64, not 32
  EXPECT_EQ(tiles[65], 4);
  EXPECT_EQ(tiles[96], 104);
  EXPECT_EQ(tiles[97], 154);
  EXPECT_EQ(tiles[192], 54);  // (4, 4): k = 24, the fourth tile
  EXPECT_EQ(tiles[193], 24);
  EXPECT_EQ(tiles[224], 124);
  EXPECT_EQ(tiles[225], 174);
  EXPECT_EQ(tiles[66], 0);  // (5, 0): padding
  EXPECT_EQ(from_tiles(kTexFormatRGBA8, 5, 5, tiles), rows);
}

TEST(GxMapTexture, Rgba8DecodesHandMadeBytes) {
  TextureObject t;
  t.format = kTexFormatRGBA8;
  t.width = t.height = 4;
  t.data.assign(64, 0);
  // Texel (2, 1) is texel 6 of the tile: (a, r) at bytes 12, 13, (g, b) at 44, 45.
  t.data[12] = 7;
  t.data[13] = 200;
  t.data[44] = 100;
  t.data[45] = 50;
  EXPECT_EQ(texel_at(t, 2, 1), (Color8{200, 100, 50, 7}));
  EXPECT_EQ(texel_at(t, 1, 2), (Color8{0, 0, 0, 0}));
  EXPECT_EQ(tiled_size(kTexFormatRGBA8, 256, 256), 2 * tiled_size(kTexFormatRGB565, 256, 256));
}

// ---- bilinear on the colour formats ----

// The 2 x 2 sample point of the I8 test (gx_texture_test BilinearWeightsIn2D): u = 64 + 33,
// v = 64 + 10, so fs = 33, ft = 10 and the weights of (0,0), (1,0), (0,1), (1,1) are
// 95*118 = 11210, 33*118 = 3894, 95*10 = 950, 33*10 = 330 (of 16384).
constexpr s32 kU = 97, kV = 74;

TEST(GxMapTexture, Rgb565BilinearFiltersTheExpandedComponents) {
  // A = 0xF804 (r 31, g 0, b 4), B = 0x07F4 (0, 63, 20), C = 0x841F (16, 32, 31),
  // D = 0x4200 (8, 16, 0); row 0 = {A, B}, row 1 = {C, D}. Expanded: A (255, 0, 33),
  // B (0, 255, 165), C (132, 130, 255), D (66, 65, 0).
  TextureObject t;
  t.format = kTexFormatRGB565;
  t.width = t.height = 2;
  t.data = to_tiles(kTexFormatRGB565, 2, 2, {0xF8, 0x04, 0x07, 0xF4, 0x84, 0x1F, 0x42, 0x00});
  // r = (255*11210 + 132*950 + 66*330) >> 14 = 3005730 >> 14 = 183
  // g = (255*3894 + 130*950 + 65*330) >> 14 = 1137920 >> 14 = 69
  // b = (33*11210 + 165*3894 + 255*950) >> 14 = 1254690 >> 14 = 76; a = 255 everywhere.
  EXPECT_EQ(sample_texture(t, kU, kV), (Color8{183, 69, 76, 255}));
  // Texel centres give the expanded texels themselves.
  EXPECT_EQ(sample_texture(t, 192, 64), (Color8{0, 255, 165, 255}));
  EXPECT_EQ(sample_texture(t, 64, 192), (Color8{132, 130, 255, 255}));
}

TEST(GxMapTexture, Rgba8BilinearFiltersEachComponentOnItsOwn) {
  // (r, g, b, a): A (10, 255, 0, 1), B (200, 0, 0, 2), C (60, 0, 0, 3), D (250, 0, 255, 4).
  TextureObject t;
  t.format = kTexFormatRGBA8;
  t.width = t.height = 2;
  t.data =
      to_tiles(kTexFormatRGBA8, 2, 2, {10, 255, 0, 1, 200, 0, 0, 2, 60, 0, 0, 3, 250, 0, 255, 4});
  // r as the I8 test: 1030400 >> 14 = 62; g = 255*11210 >> 14 = 174; b = 255*330 >> 14 = 5;
  // a = (11210 + 2*3894 + 3*950 + 4*330) >> 14 = 23168 >> 14 = 1.
  EXPECT_EQ(sample_texture(t, kU, kV), (Color8{62, 174, 5, 1}));
  // Clamped at the corner beyond texel (0, 0): the texel itself.
  EXPECT_EQ(sample_texture(t, -500, -500), (Color8{10, 255, 0, 1}));
}

// ---- the thickness map's texture ----

std::vector<float> map_of(const std::vector<int>& bytes_rgb) {
  std::vector<float> out;
  for (int b : bytes_rgb) out.push_back(static_cast<float>(b / 255.0));
  return out;
}

TEST(GxMapTexture, GreyMapIsI8AndExactForEightBitTexels) {
  // 2 x 2, r = g = b: row 0 (the image's bottom row, v = 0) = {10, 200}, row 1 = {60, 250}.
  const ThicknessTexture tt = thickness_texture(
      2, 2, map_of({10, 10, 10, 200, 200, 200, 60, 60, 60, 250, 250, 250}), TexFormat::I8);
  EXPECT_EQ(tt.format_name, "GX_TF_I8");
  EXPECT_EQ(tt.texture.format, kTexFormatI8);
  EXPECT_EQ(tt.scale, 1.0);
  EXPECT_EQ(tt.texture.data.size(), 32u);
  EXPECT_EQ(texel_at(tt.texture, 0, 0).r, 10);
  EXPECT_EQ(texel_at(tt.texture, 1, 1).r, 250);
  // Bottom row first: GX's t = 0 is memory row 0 = the map's v = 0, so the identity texgen's
  // t = v = 0.25 (row 0's centre, 64 in s17.7 at H = 2) reads row 0.
  EXPECT_EQ(raster_texcoord(0.25f * 2), 64);
  EXPECT_EQ(sample_texture(tt.texture, 192, 64), (Color8{200, 200, 200, 200}));
  // The I8 sample of gx_texture_test, through the map's texture: 62.
  EXPECT_EQ(sample_texture(tt.texture, kU, kV).r, 62);
}

TEST(GxMapTexture, ColourMapIsRgba8AndExactForEightBitTexels) {
  const ThicknessTexture tt =
      thickness_texture(3, 1, map_of({255, 0, 7, 1, 128, 254, 90, 91, 92}), TexFormat::RGBA8);
  EXPECT_EQ(tt.format_name, "GX_TF_RGBA8");
  EXPECT_EQ(tt.texture.format, kTexFormatRGBA8);
  EXPECT_EQ(tt.texture.wrap_s, 0);  // GX_CLAMP, as the reference's CLAMP_TO_EDGE
  EXPECT_EQ(texel_at(tt.texture, 0, 0), (Color8{255, 0, 7, 255}));
  EXPECT_EQ(texel_at(tt.texture, 1, 0), (Color8{1, 128, 254, 255}));
  EXPECT_EQ(texel_at(tt.texture, 2, 0), (Color8{90, 91, 92, 255}));
}

TEST(GxMapTexture, Rgb565MapStoresTheNearestExpansion) {
  // 0.2 = 51/255: r, b fields 6 -> 49 (57 from 7 is further); g field 13 -> 52 (48 from 12 is
  // further). 1 and 0 are exact.
  const ThicknessTexture tt = thickness_texture(
      3, 1, {0.2f, 0.2f, 0.2f, 1.0f, 0.0f, 1.0f, 0.0f, 1.0f, 0.0f}, TexFormat::RGB565);
  EXPECT_EQ(tt.format_name, "GX_TF_RGB565");
  EXPECT_EQ(texel_at(tt.texture, 0, 0), (Color8{49, 52, 49, 255}));
  EXPECT_EQ(texel_at(tt.texture, 1, 0), (Color8{255, 0, 255, 255}));
  EXPECT_EQ(texel_at(tt.texture, 2, 0), (Color8{0, 255, 0, 255}));
  // Every 8-bit value k: no 5- or 6-bit field expands nearer to k than the one stored, and the
  // error is at most 4 (5 bits: expansions 8.2 apart) or 2 (6 bits: 4.0 apart).
  for (int k = 0; k <= 255; ++k) {
    const u16 v = nearest_rgb565(k / 255.0, k / 255.0, k / 255.0);
    const int r = expand5(v >> 11), g = expand6((v >> 5) & 63);
    for (int q = 0; q < 32; ++q) EXPECT_LE(std::abs(r - k), std::abs(expand5(q) - k)) << k;
    for (int q = 0; q < 64; ++q) EXPECT_LE(std::abs(g - k), std::abs(expand6(q) - k)) << k;
    EXPECT_LE(std::abs(r - k), 4) << k;
    EXPECT_LE(std::abs(g - k), 2) << k;
    EXPECT_EQ(expand5(v & 31), r) << k;
  }
}

// A field's 8-bit value by its definition, the field's bits repeated from the top down (the
// hardware's bit replication), written here independently of texture_decoder.h.
int replicated(int field, int bits) {
  int out = 0;
  for (int k = 0; k < 8; ++k) out = out << 1 | (field >> (bits - 1 - k % bits) & 1);
  return out;
}

TEST(GxMapTexture, TheNearestFieldIsTheLowestOfTheNearestExpansionsForAnyTarget) {
  // Targets every 1/8 of a step over 0..255 (the midpoints between two expansions among them,
  // where the lower field must win) and beyond both ends (clamped): the field nearest_field
  // gives is the lowest of those whose expansion is nearest, found by trying every field.
  for (int bits : {3, 4, 5, 6, 8}) {  // the fields of the GX formats
    for (int j = -16; j <= 255 * 8 + 16; ++j) {
      const double v = j / 8.0, target = std::clamp(v, 0.0, 255.0);
      int lowest_nearest = 0;
      for (int f = 1; f < 1 << bits; ++f)
        if (std::abs(replicated(f, bits) - target) <
            std::abs(replicated(lowest_nearest, bits) - target))
          lowest_nearest = f;
      ASSERT_EQ(nearest_field(v, bits), lowest_nearest) << bits << " bits, v " << v;
    }
  }
}

TEST(GxMapTexture, FloatMapOverOneIsNormalisedToItsLargestTexel) {
  // Texels 0.5, 1, 2 (an EXR map): 255 stands for 2, so 1 -> round(127.5) = 128, 0.5 -> 64.
  const ThicknessTexture tt =
      thickness_texture(3, 1, {0.5f, 0.5f, 0.5f, 1, 1, 1, 2, 2, 2}, TexFormat::I8);
  EXPECT_EQ(tt.scale, 2.0);
  EXPECT_EQ(texel_at(tt.texture, 0, 0).r, 64);
  EXPECT_EQ(texel_at(tt.texture, 1, 0).r, 128);
  EXPECT_EQ(texel_at(tt.texture, 2, 0).r, 255);
}

}  // namespace
}  // namespace lt::gx
