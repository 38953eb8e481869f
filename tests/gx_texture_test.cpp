// The gx texture unit (src/gx/texture_unit.h, gx-hardware.md §3.2-3.4): GX tile order for
// I8 and IA8, the s17.7 texture coordinate and Dolphin's 7-bit bilinear filter with its wrap
// modes. Expectations are worked out in the test from the documented formulas.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gx/rasteriser.h"
#include "gx/texture_unit.h"

namespace lt::gx {
namespace {

constexpr u8 kI8 = 1, kIA8 = 3;
constexpr u8 kClamp = 0, kRepeat = 1, kMirror = 2;

TextureObject i8_texture(int w, int h, const std::vector<u8>& row_major, u8 wrap_s = kClamp,
                         u8 wrap_t = kClamp, bool linear = true) {
  TextureObject t;
  t.format = kI8;
  t.width = w;
  t.height = h;
  t.data = to_tiles(kI8, w, h, row_major);
  t.wrap_s = wrap_s;
  t.wrap_t = wrap_t;
  t.linear = linear;
  return t;
}

Color8 gray(u8 v) {
  return Color8{v, v, v, v};
}

// ---- tile layout ----

TEST(GxTexture, I8TileAddressing16x8) {
  std::vector<u8> rows(16 * 8);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) rows[y * 16 + x] = static_cast<u8>(x + 16 * y);
  ASSERT_EQ(tiled_size(kI8, 16, 8), 128u);  // 2 x 2 tiles of 32 bytes
  const std::vector<u8> tiles = to_tiles(kI8, 16, 8, rows);
  ASSERT_EQ(tiles.size(), 128u);
  // Offsets by hand from ((y>>2)*ceil(W/8) + (x>>3))*32 + (y&3)*8 + (x&7), W = 16.
  EXPECT_EQ(tiles[0], 0);              // (0, 0)
  EXPECT_EQ(tiles[7], 7);              // (7, 0)
  EXPECT_EQ(tiles[32], 8);             // (8, 0): second tile
  EXPECT_EQ(tiles[8], 16);             // (0, 1): second row of the first tile
  EXPECT_EQ(tiles[19], 3 + 16 * 2);    // (3, 2): 2*8 + 3
  EXPECT_EQ(tiles[57], 9 + 16 * 3);    // (9, 3): 32 + 3*8 + 1
  EXPECT_EQ(tiles[64], 16 * 4);        // (0, 4): second tile row
  EXPECT_EQ(tiles[127], 15 + 16 * 7);  // (15, 7): 3*32 + 3*8 + 7
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x)
      EXPECT_EQ(tiles[((y >> 2) * 2 + (x >> 3)) * 32 + (y & 3) * 8 + (x & 7)], x + 16 * y);
  EXPECT_EQ(from_tiles(kI8, 16, 8, tiles), rows);
}

TEST(GxTexture, I8PaddedImage10x5) {
  std::vector<u8> rows(10 * 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 10; ++x) rows[y * 10 + x] = static_cast<u8>(1 + x + 10 * y);
  // ceil(10/8) = 2 tiles across, ceil(5/4) = 2 down: 128 bytes.
  ASSERT_EQ(tiled_size(kI8, 10, 5), 128u);
  const std::vector<u8> tiles = to_tiles(kI8, 10, 5, rows);
  ASSERT_EQ(tiles.size(), 128u);
  EXPECT_EQ(tiles[97], 1 + 9 + 40);  // (9, 4): (1*2 + 1)*32 + 0*8 + 1
  EXPECT_EQ(tiles[29], 1 + 5 + 30);  // (5, 3): 3*8 + 5
  EXPECT_EQ(tiles[40], 1 + 8 + 10);  // (8, 1): 32 + 8
  EXPECT_EQ(tiles[34], 0);           // (10, 0): padding column
  EXPECT_EQ(tiles[72], 0);           // (0, 5): padding row
  int nonzero = 0;
  for (u8 b : tiles) nonzero += b != 0;
  EXPECT_EQ(nonzero, 50);  // exactly the 50 texels; all padding is zero
  EXPECT_EQ(from_tiles(kI8, 10, 5, tiles), rows);
  // Sizes of other shapes: a 1-row LUT of width W takes ceil(W/8)*32 bytes (§3.4).
  EXPECT_EQ(tiled_size(kI8, 1, 1), 32u);
  EXPECT_EQ(tiled_size(kI8, 256, 1), 32u * 32u);
  EXPECT_EQ(tiled_size(kI8, 9, 4), 64u);
}

TEST(GxTexture, IA8TileLayoutStoresAlphaFirst) {
  // Row-major (I, A) pairs, I = 1 + x + 6y, A = 100 + x + 6y, in a 6 x 5 image.
  std::vector<u8> rows(6 * 5 * 2);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 6; ++x) {
      rows[(y * 6 + x) * 2] = static_cast<u8>(1 + x + 6 * y);
      rows[(y * 6 + x) * 2 + 1] = static_cast<u8>(100 + x + 6 * y);
    }
  }
  // 4x4-texel tiles of 32 bytes: ceil(6/4) = 2 across, ceil(5/4) = 2 down.
  ASSERT_EQ(tiled_size(kIA8, 6, 5), 128u);
  const std::vector<u8> tiles = to_tiles(kIA8, 6, 5, rows);
  ASSERT_EQ(tiles.size(), 128u);
  // Offset ((y>>2)*2 + (x>>2))*32 + ((y&3)*4 + (x&3))*2; alpha there, intensity one after.
  EXPECT_EQ(tiles[0], 100);  // (0, 0) alpha
  EXPECT_EQ(tiles[1], 1);    // (0, 0) intensity
  EXPECT_EQ(tiles[2], 101);  // (1, 0)
  EXPECT_EQ(tiles[3], 2);
  EXPECT_EQ(tiles[32], 104);  // (4, 0): second tile
  EXPECT_EQ(tiles[33], 5);
  EXPECT_EQ(tiles[12], 100 + 2 + 6);  // (2, 1): (4 + 2)*2
  EXPECT_EQ(tiles[13], 1 + 2 + 6);
  EXPECT_EQ(tiles[98], 100 + 5 + 24);  // (5, 4): 3*32 + 1*2
  EXPECT_EQ(tiles[99], 1 + 5 + 24);
  EXPECT_EQ(tiles[36], 0);  // (6, 0): padding
  EXPECT_EQ(from_tiles(kIA8, 6, 5, tiles), rows);
  EXPECT_EQ(tiled_size(kIA8, 8, 1), 64u);
}

// ---- fixed point ----

TEST(GxTexture, FixedTexcoordTruncatesTowardZeroAndWrapsInItsField) {
  // The rasteriser's s17.7 coordinate of s * size (the XF scales by the size per vertex).
  EXPECT_EQ(raster_texcoord(0.3f * 4), 153);    // 153.6
  EXPECT_EQ(raster_texcoord(-0.3f * 4), -153);  // -153.6: toward zero, not floor (-154)
  EXPECT_EQ(raster_texcoord(0.5f), 64);
  EXPECT_EQ(raster_texcoord(1024.0f), 131072);
  EXPECT_EQ(raster_texcoord(0.0001f * 8), 0);   // 0.1024
  EXPECT_EQ(raster_texcoord(-0.0001f * 8), 0);  // -0.1024
  EXPECT_EQ(raster_texcoord(-0.001f * 8), -1);  // -1.024
  // The signed 24-bit field [DSW Tev.h `signed s : 24`]: 2^23 - 1 = 8388607 and -2^23; past
  // them the value wraps, as the bit-field store does.
  EXPECT_EQ(raster_texcoord(65535.9921875f), 8388607);   // exactly 2^23 - 1
  EXPECT_EQ(raster_texcoord(65536.0f), -8388608);        // 2^23 wraps to -2^23
  EXPECT_EQ(raster_texcoord(-65536.0f), -8388608);       // exactly -2^23
  EXPECT_EQ(raster_texcoord(-65536.0078125f), 8388607);  // -2^23 - 1 wraps to 2^23 - 1
  // Out of the 32-bit range, infinite or NaN: x86's INT_MIN, whose low 24 bits are 0.
  EXPECT_EQ(raster_texcoord(1e6f * 1024), 0);
  EXPECT_EQ(raster_texcoord(-1e6f * 1024), 0);
  EXPECT_EQ(raster_texcoord(std::numeric_limits<float>::infinity()), 0);
  EXPECT_EQ(raster_texcoord(-std::numeric_limits<float>::infinity()), 0);
  EXPECT_EQ(raster_texcoord(std::numeric_limits<float>::quiet_NaN()), 0);
}

// ---- filtering ----

TEST(GxTexture, WorkedVectorOfTheSpec) {
  // §3.3: W = 4, T = {0, 100, 200, 255}, s = 0.3 -> u = 153, i0 = 0, f = 89 ->
  // (0 * 39 + 100 * 89) >> 7 = 8900 >> 7 = 69.
  const TextureObject t = i8_texture(4, 1, {0, 100, 200, 255});
  const s32 u = raster_texcoord(0.3f * 4);
  EXPECT_EQ(u, 153);
  EXPECT_EQ(sample_texture(t, u, 0), gray(69));
  // s = 0: u - 64 = -64 -> i0 = -1, i1 = 0, both clamp to texel 0.
  EXPECT_EQ(sample_texture(t, raster_texcoord(0.0f), 0), gray(0));
  // The same with a non-zero first texel, so the clamp is visible: 50.
  EXPECT_EQ(sample_texture(i8_texture(4, 1, {50, 100, 200, 255}), 0, 0), gray(50));
}

TEST(GxTexture, BilinearWeightsIn2D) {
  // 2 x 2: row 0 = {10, 200}, row 1 = {60, 250}. u = 64 + 33 -> fs = 33; v = 64 + 10 -> ft = 10.
  // Weights (128-fs)(128-ft) = 95*118 = 11210, fs(128-ft) = 33*118 = 3894, (128-fs)ft = 950,
  // fs ft = 330 (sum 16384). 10*11210 + 200*3894 + 60*950 + 250*330 = 1030400; >> 14 = 62
  // (62.89: truncated once, not rounded to 63, and not two 7-bit passes, which give 61).
  const TextureObject t = i8_texture(2, 2, {10, 200, 60, 250});
  EXPECT_EQ(sample_texture(t, 97, 74), gray(62));
  // At a texel centre the texel itself: u = v = 64 + 128 -> (1, 1).
  EXPECT_EQ(sample_texture(t, 192, 192), gray(250));
  // Exactly between the four centres: (10 + 200 + 60 + 250) * 64 * 64 >> 14 = 130.
  EXPECT_EQ(sample_texture(t, 128, 128), gray(130));
}

TEST(GxTexture, IA8FiltersIntensityAndAlphaSeparately) {
  TextureObject t;
  t.format = kIA8;
  t.width = 2;
  t.height = 1;
  t.data = to_tiles(kIA8, 2, 1, {10, 200, 250, 0});  // (I, A) = (10, 200), (250, 0)
  // fs = 32: I = (10*96 + 250*32) >> 7 = 70, A = (200*96 + 0*32) >> 7 = 150.
  EXPECT_EQ(sample_texture(t, 96, 0), (Color8{70, 70, 70, 150}));
  t.linear = false;
  EXPECT_EQ(sample_texture(t, 130, 0), (Color8{250, 250, 250, 0}));
  EXPECT_EQ(sample_texture(t, 5, 0), (Color8{10, 10, 10, 200}));
}

TEST(GxTexture, WrapModesAtBothEnds) {
  // Nearest on T = {10, 20, 30, 40}: u = 128 i + 5 addresses texel index i = -6..9 (u >> 7
  // floors, so u = -123 is index -1). Expected indices by hand:
  //   CLAMP  clamp(i, 0, 3); REPEAT i & 3; MIRROR period 8: 0 1 2 3 3 2 1 0.
  const int clamp[16] = {0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 3, 3, 3, 3, 3, 3};
  const int repeat[16] = {2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1, 2, 3, 0, 1};
  const int mirror[16] = {2, 3, 3, 2, 1, 0, 0, 1, 2, 3, 3, 2, 1, 0, 0, 1};
  const std::vector<u8> row{10, 20, 30, 40};
  const TextureObject tc = i8_texture(4, 1, row, kClamp, kClamp, false);
  const TextureObject tr = i8_texture(4, 1, row, kRepeat, kClamp, false);
  const TextureObject tm = i8_texture(4, 1, row, kMirror, kClamp, false);
  const TextureObject t3 = i8_texture(4, 1, row, 3, kClamp, false);  // behaves as clamp
  for (int k = 0; k < 16; ++k) {
    const int i = k - 6;
    const s32 u = 128 * i + 5;
    EXPECT_EQ(sample_texture(tc, u, 0).r, row[clamp[k]]) << "clamp i=" << i;
    EXPECT_EQ(sample_texture(tr, u, 0).r, row[repeat[k]]) << "repeat i=" << i;
    EXPECT_EQ(sample_texture(tm, u, 0).r, row[mirror[k]]) << "mirror i=" << i;
    EXPECT_EQ(sample_texture(t3, u, 0).r, row[clamp[k]]) << "mode 3 i=" << i;
  }
  // Bilinear at the left end, u = 0: taps -1 and 0 with f = 64. CLAMP: 10; REPEAT: texels 3 and
  // 0, (40*64 + 10*64) >> 7 = 25; MIRROR: -1 -> 0, so 10.
  const TextureObject lc = i8_texture(4, 1, row, kClamp);
  const TextureObject lr = i8_texture(4, 1, row, kRepeat);
  const TextureObject lm = i8_texture(4, 1, row, kMirror);
  EXPECT_EQ(sample_texture(lc, 0, 0).r, 10);
  EXPECT_EQ(sample_texture(lr, 0, 0).r, 25);
  EXPECT_EQ(sample_texture(lm, 0, 0).r, 10);
  // Right end, u = 512: taps 3 and 4. CLAMP 40; REPEAT 4 -> 0: 25; MIRROR 4 -> 3: 40.
  EXPECT_EQ(sample_texture(lc, 512, 0).r, 40);
  EXPECT_EQ(sample_texture(lr, 512, 0).r, 25);
  EXPECT_EQ(sample_texture(lm, 512, 0).r, 40);
  // The t direction wraps independently: 1 x 4 column, REPEAT in t.
  const TextureObject col = i8_texture(1, 4, row, kClamp, kRepeat);
  EXPECT_EQ(sample_texture(col, 0, 0).r, 25);
  EXPECT_EQ(sample_texture(col, 0, 64 + 128 * 2).r, 30);
}

TEST(GxTexture, RepeatOnANonPowerOfTwoSizeMasksWithSizeMinusOne) {
  // Dolphin's model of the hardware: REPEAT is i & (W - 1) even when W is not a power of two
  // [DSW WrapCoord, quoting YAGCD]. W = 3: i & 2 maps i = 0..5 to 0, 0, 2, 2, 0, 0 (a modulo
  // would give 0, 1, 2, 0, 1, 2).
  const std::vector<u8> row{10, 20, 30};
  const TextureObject t = i8_texture(3, 1, row, kRepeat, kClamp, false);
  const int expected[6] = {0, 0, 2, 2, 0, 0};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(sample_texture(t, 128 * i, 0).r, row[expected[i]]) << i;
}

TEST(GxTexture, NearestPicksTheContainingTexel) {
  std::vector<u8> rows(16);
  for (int i = 0; i < 16; ++i) rows[i] = static_cast<u8>(7 * i + 3);
  const TextureObject t = i8_texture(4, 4, rows, kClamp, kClamp, false);
  EXPECT_EQ(sample_texture(t, 128 * 2 + 127, 128 * 1).r, rows[1 * 4 + 2]);
  // No half-texel offset in nearest mode: u = 2*128 + 10 is still texel 2 (bilinear's -64 would
  // make it 1).
  EXPECT_EQ(sample_texture(t, 128 * 2 + 10, 128 * 3 + 127).r, rows[3 * 4 + 2]);
  EXPECT_EQ(sample_texture(t, -1, -1).r, rows[0]);           // floor(-1/128) = -1, clamped
  EXPECT_EQ(sample_texture(t, 100000, 100000).r, rows[15]);  // far right and bottom
}

TEST(GxTexture, OneRowTextureIsTheOneDimensionalLerpForEveryU) {
  // For a height-1 texture both t taps are row 0, so the 2D formula reduces to
  // (T[i0]*(128-f) + T[i1]*f) >> 7 (§3.3). The indices are computed here with floor division.
  const std::vector<u8> T{3, 250, 17, 128, 0, 255, 90, 41};
  const int W = 8;
  for (u8 mode : {kClamp, kRepeat, kMirror}) {
    const TextureObject tex = i8_texture(W, 1, T, mode);
    auto index = [&](int i) {
      if (mode == kClamp) return i < 0 ? 0 : (i > W - 1 ? W - 1 : i);
      if (mode == kRepeat) return ((i % W) + W) % W;
      const int m = ((i % (2 * W)) + 2 * W) % (2 * W);  // mirror: period 2W, reflected half
      return m < W ? m : 2 * W - 1 - m;
    };
    for (int u = -400; u <= W * 128 + 400; ++u) {
      const int d = u - 64;
      const int i0 = static_cast<int>(std::floor(d / 128.0));
      const int f = d - 128 * i0;
      const int expected = (T[index(i0)] * (128 - f) + T[index(i0 + 1)] * f) >> 7;
      for (s32 v : {0, -77, 500}) {
        const Color8 got = sample_texture(tex, u, v);
        ASSERT_EQ(got, gray(static_cast<u8>(expected)))
            << "mode " << int(mode) << " u " << u << " v " << v;
      }
    }
  }
}

TEST(GxTextureDeathTest, UnknownFormatIsABug) {
  // 7 is no GX_TF_* format (RGBA8 is 6, CI4 8) [OGC gx.h L291-303]: every real one is modelled.
  EXPECT_DEATH(tiled_size(7, 4, 4), "GX_TF_\\* format");
}

}  // namespace
}  // namespace lt::gx
