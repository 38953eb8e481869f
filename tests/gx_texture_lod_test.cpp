// The texture unit's level of detail (src/gx/texture_lod.h, gx-hardware.md §3.5): Dolphin's
// software renderer's LOD of a 2x2 quad, its clamps and filters, the level(s) a LOD picks, the
// levels' places in memory, and libogc's GX_InitTexObjLOD fields. Every expectation is worked
// by hand from the rules as Dolphin writes them [DSW Rasterizer.cpp FixedLog2, CalculateLOD]
// [DSW TextureSampler.cpp Sample, SampleMip] [OGC gx.c GX_InitTexObjLOD], not from the code.
#include <gtest/gtest.h>

#include <vector>

#include "gx/texture_format.h"
#include "gx/texture_lod.h"
#include "gx/texture_unit.h"

namespace lt::gx {
namespace {

TextureLod lod_mode(u8 min_filter, s32 bias, u8 min_lod, u8 max_lod, bool diagonal = false) {
  TextureLod m;
  m.min_filter = min_filter;
  m.bias = static_cast<std::int8_t>(bias);
  m.min_lod = min_lod;
  m.max_lod = max_lod;
  m.diagonal = diagonal;
  return m;
}

// A quad whose u moves du_dx a pixel across and du_dy down, v likewise.
QuadTexcoords quad_moving(float du_dx, float dv_dx, float du_dy, float dv_dy) {
  return {10.0f, 20.0f, 10.0f + du_dx, 20.0f + dv_dx, 10.0f + du_dy, 20.0f + dv_dy};
}

TEST(GxTextureLod, FixedLog2IsTheExponentAndTheMantissasTopFourBits) {
  // 1.0f: exponent 127, mantissa 0: 127 * 16 - 2032 = 0. 2.0f: 16; 0.5f: -16.
  EXPECT_EQ(fixed_log2(1.0f), 0);
  EXPECT_EQ(fixed_log2(2.0f), 16);
  EXPECT_EQ(fixed_log2(0.5f), -16);
  // 3.0f = 1.5 * 2: exponent 128 (16), mantissa 0x400000 >> 19 = 8: 24 (log2 3 = 1.585 -> 25.4).
  EXPECT_EQ(fixed_log2(3.0f), 24);
  // 1.25f: mantissa 0x200000 >> 19 = 4. 1.99f: mantissa 0x7EB852 >> 19 = 15.
  EXPECT_EQ(fixed_log2(1.25f), 4);
  EXPECT_EQ(fixed_log2(1.99f), 15);
  // 0: exponent 0, -2032; the sign bit is not read.
  EXPECT_EQ(fixed_log2(0.0f), -2032);
  EXPECT_EQ(fixed_log2(-2.0f), 16);
}

TEST(GxTextureLod, EdgeLodTakesTheLargerDeltaAndDiagonalTheirSums) {
  const TextureLod edge = lod_mode(6, 0, 0, 160);
  // du/dx 2, du/dy 2, dv 0: edge max(2, 2) = 2 -> 16; diagonal 2 + 2 = 4 -> 32.
  EXPECT_EQ(quad_lod(edge, true, quad_moving(2, 0, 2, 0)).lod, 16);
  EXPECT_EQ(quad_lod(lod_mode(6, 0, 0, 160, true), true, quad_moving(2, 0, 2, 0)).lod, 32);
  // v's delta wins when larger: du 1, dv/dy 8 -> 48.
  EXPECT_EQ(quad_lod(edge, true, quad_moving(1, 0, 0, 8)).lod, 48);
  // Deltas are absolute: a mirrored quad gives the same LOD.
  EXPECT_EQ(quad_lod(edge, true, quad_moving(-4, 0, 0, -1)).lod, 32);
}

TEST(GxTextureLod, BiasIsS2_5HalvedArithmeticallyThenTheClampMaxFirst) {
  // Delta 4 -> 32; bias +1.0 (32 in s2.5) >> 1 = 16 -> 48; -1.0 (-32) -> -16 -> 16;
  // -3/32 (-3) >> 1 = -2 (the shift floors) -> 30.
  EXPECT_EQ(quad_lod(lod_mode(6, 32, 0, 160), true, quad_moving(4, 0, 0, 0)).lod, 48);
  EXPECT_EQ(quad_lod(lod_mode(6, -32, 0, 160), true, quad_moving(4, 0, 0, 0)).lod, 16);
  EXPECT_EQ(quad_lod(lod_mode(6, -3, 0, 160), true, quad_moving(4, 0, 0, 0)).lod, 30);
  // Clamped to max 40, or up to min 24 (delta 1 -> 0).
  EXPECT_EQ(quad_lod(lod_mode(6, 0, 0, 40), true, quad_moving(8, 0, 0, 0)).lod, 40);
  EXPECT_EQ(quad_lod(lod_mode(6, 0, 24, 40), true, quad_moving(1, 0, 0, 0)).lod, 24);
  // min 48 > max 32: above max gives max (32), below it gives min (48).
  EXPECT_EQ(quad_lod(lod_mode(6, 0, 48, 32), true, quad_moving(8, 0, 0, 0)).lod, 32);
  EXPECT_EQ(quad_lod(lod_mode(6, 0, 48, 32), true, quad_moving(2, 0, 0, 0)).lod, 48);
}

TEST(GxTextureLod, TheFilterIsChosenFromTheLodBeforeItsClamp) {
  // Min GX_NEAR (0), mag GX_LINEAR, max LOD 0: a minified quad (LOD 16) is nearest although the
  // clamp then leaves LOD 0; a magnified one (LOD -16) linear.
  const LodChoice minified = quad_lod(lod_mode(0, 0, 0, 0), true, quad_moving(2, 0, 0, 0));
  EXPECT_FALSE(minified.linear);
  EXPECT_EQ(minified.lod, 0);
  EXPECT_TRUE(quad_lod(lod_mode(0, 0, 0, 0), true, quad_moving(0.5f, 0, 0, 0)).linear);
  // LOD exactly 0 is magnification: the mag filter (here near, min linear).
  EXPECT_FALSE(quad_lod(lod_mode(4, 0, 0, 0), false, quad_moving(1, 0, 0, 0)).linear);
}

TEST(GxTextureLod, PointMipRoundsAtHalfAndLinearMipBlendsSixteenths) {
  const TextureLod point = lod_mode(1, 0, 0, 160), linear = lod_mode(2, 0, 0, 160);
  EXPECT_EQ(mip_choice(point, 23).level, 1);  // 1 + 7/16
  EXPECT_EQ(mip_choice(point, 24).level, 2);  // 1 + 8/16 rounds up
  EXPECT_EQ(mip_choice(point, 24).fraction, 0);
  EXPECT_EQ(mip_choice(linear, 20).level, 1);
  EXPECT_EQ(mip_choice(linear, 20).fraction, 4);
  EXPECT_EQ(mip_choice(linear, 0).level, 0);                   // LOD 0: level 0
  EXPECT_EQ(mip_choice(lod_mode(4, 0, 0, 160), 40).level, 0);  // no mip filter
}

TEST(GxTextureLod, ReachableLevelsAndWhenTheLodMatters) {
  EXPECT_EQ(reachable_levels(lod_mode(6, 0, 0, 32)), 3);  // up to level 2
  EXPECT_EQ(reachable_levels(lod_mode(6, 0, 0, 40)), 4);  // 2.5 blends level 3
  EXPECT_EQ(reachable_levels(lod_mode(6, 0, 48, 0)), 4);  // min LOD past max is reached
  EXPECT_EQ(reachable_levels(lod_mode(4, 0, 0, 40)), 1);
  EXPECT_FALSE(lod_matters(lod_mode(4, 0, 0, 0), true));
  EXPECT_FALSE(lod_matters(lod_mode(6, 0, 0, 0), true));  // GX_InitTexObj's mipmap default
  EXPECT_TRUE(lod_matters(lod_mode(6, 0, 0, 16), true));
  EXPECT_TRUE(lod_matters(lod_mode(0, 0, 0, 0), true));  // min near, mag linear
}

TEST(GxTextureLod, LibogcWritesTheFieldsAsItsConversionsGive) {
  // GX_LIN_MIP_LIN (5) -> 6; bias -1.0 -> (u32)(-32) & 0xff = 0xE0 = -32; edgelod GX_TRUE ->
  // diagonal 0; min 11 -> 10 -> 160; max 2.5 -> 40.
  const TextureLod a = libogc_texture_lod(5, 11.0f, 2.5f, -1.0f, true, true, 2);
  EXPECT_EQ(a.min_filter, 6);
  EXPECT_EQ(a.bias, -32);
  EXPECT_FALSE(a.diagonal);
  EXPECT_TRUE(a.bias_clamp);
  EXPECT_EQ(a.max_aniso, 2);
  EXPECT_EQ(a.min_lod, 160);
  EXPECT_EQ(a.max_lod, 40);
  // 4.0 is taken as 3.99 (127.68 -> 127), below -4 as -4 (-128); GX_NEAR_MIP_NEAR (2) -> 1.
  EXPECT_EQ(libogc_texture_lod(2, 0, 0, 4.0f, false, false, 0).bias, 127);
  EXPECT_EQ(libogc_texture_lod(2, 0, 0, -9.0f, false, false, 0).bias, -128);
  EXPECT_EQ(libogc_texture_lod(2, 0, 0, 0, false, false, 0).min_filter, 1);
  EXPECT_TRUE(libogc_texture_lod(2, 0, 0, 0, false, false, 0).diagonal);
}

// An 8x8 I8 texture with two levels: level 0 all 10 (two 8x4 tiles, 64 bytes), level 1 4x4
// texels 16 y + x + 100 (one tile, 32 bytes, right after).
TextureObject two_level_i8(u8 min_filter) {
  TextureObject t;
  t.format = 1;
  t.width = t.height = 8;
  t.levels = 2;
  t.linear = false;
  t.lod = lod_mode(min_filter, 0, 0, 16);
  t.data = to_tiles(1, 8, 8, std::vector<u8>(64, 10));
  std::vector<u8> level1(16);
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x)
      level1[static_cast<size_t>(y * 4 + x)] = static_cast<u8>(16 * y + x + 100);
  const std::vector<u8> tiles1 = to_tiles(1, 4, 4, level1);
  t.data.insert(t.data.end(), tiles1.begin(), tiles1.end());
  return t;
}

TEST(GxTextureLod, LevelsSitAfterTheWholeTilesBeforeThemAndTakeTheCoordinateShifted) {
  EXPECT_EQ(level_offset(1, 8, 8, 1), 64u);
  EXPECT_EQ(level_offset(0xE, 16, 16, 2), 128u + 32u);  // CMPR 8x8 blocks: 4 then 1 of 32 bytes
  const TextureObject t = two_level_i8(1);              // NEAR_MIP_NEAR
  // u = 3.5 texels of level 0 (448 in s17.7), v = 6.25 (800): level 1 reads (448 >> 1) >> 7 = 1
  // and (800 >> 1) >> 7 = 3: 16 * 3 + 1 + 100.
  const s32 u = 448, v = 800;
  const LodChoice at_level1{16, false}, at_level0{0, false};
  Color8 out;
  sample_texture_lod_at(t, &u, &v, &at_level1, 1, &out);
  EXPECT_EQ(out.r, 149);
  sample_texture_lod_at(t, &u, &v, &at_level0, 1, &out);
  EXPECT_EQ(out.r, 10);
}

TEST(GxTextureLod, LinearMipBlendsTheTwoLevelsInSixteenthsTruncated) {
  const TextureObject t = two_level_i8(2);  // NEAR_MIP_LIN
  // LOD 5/16: level 0 (10) * 11 + level 1 texel (0, 0) (100) * 5 = 610, >> 4 = 38.
  const s32 u = 0, v = 0;
  const LodChoice lod{5, false};
  Color8 out;
  sample_texture_lod_at(t, &u, &v, &lod, 1, &out);
  EXPECT_EQ(out.r, 38);
}

}  // namespace
}  // namespace lt::gx
