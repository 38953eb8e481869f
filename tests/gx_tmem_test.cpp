// gx/tmem.h: TMEM as libogc's GX_Init divides it. The expectations are libogc's numbers written
// out here (GX_Init's loops over _gxtexregionaddrtable and the TLUT regions [OGC gx.c
// L114-127, L1175-1204], __GXDefTexRegionCallback [OGC gx.c L554-571]), not the table the code
// holds.
#include <gtest/gtest.h>

#include "gx/tmem.h"

namespace lt::gx {
namespace {

TEST(GxTmem, ColourIndexedAndCmprMapsTakeTheFirstRegionsEveryOtherFormatTheSecond) {
  for (int map = 0; map < kMaxTexMaps; ++map) {
    const u32 m = static_cast<u32>(map);
    // texRegion[map]: even map * 64 KiB, odd 32 KiB above it.
    for (TexFormat f : {TexFormat::CI4, TexFormat::CI8, TexFormat::CI14X2, TexFormat::CMPR}) {
      const TexCacheRegion r = texture_cache_region(f, false, map);
      EXPECT_EQ(r.even, m << 16) << map;
      EXPECT_EQ(r.odd, (m << 16) + 0x8000) << map;
    }
    // texRegion[map + 8]: _gxtexregionaddrtable[map + 16] even, [map + 24] odd.
    const TexCacheRegion r = texture_cache_region(TexFormat::I8, false, map);
    const u32 even[8] = {0x00000, 0x90000, 0x20000, 0xB0000, 0x40000, 0x98000, 0x60000, 0xB8000};
    const u32 odd[8] = {0x80000, 0x10000, 0xA0000, 0x30000, 0x88000, 0x50000, 0xA8000, 0x70000};
    EXPECT_EQ(r.even, even[map]) << map;
    EXPECT_EQ(r.odd, odd[map]) << map;
    EXPECT_EQ(texture_cache_region(TexFormat::RGBA8, false, map).even, even[map]) << map;
  }
  // A mipmapped direct texture: texRegion[map + 16]; a colour-indexed one keeps texRegion[map].
  EXPECT_EQ(texture_cache_region(TexFormat::I8, true, 1).even, 0x90000u);
  EXPECT_EQ(texture_cache_region(TexFormat::I8, true, 5).even, 0x90000u);
  EXPECT_EQ(texture_cache_region(TexFormat::CI8, true, 5).even, 0x50000u);
}

TEST(GxTmem, EachMapsRegionOfOneKindIsItsOwn) {
  for (bool indexed : {false, true})
    for (int a = 0; a < kMaxTexMaps; ++a)
      for (int b = a + 1; b < kMaxTexMaps; ++b) {
        const TexFormat f = indexed ? TexFormat::CI8 : TexFormat::RGB565;
        EXPECT_FALSE(
            regions_overlap(texture_cache_region(f, false, a), texture_cache_region(f, false, b)))
            << a << " " << b;
      }
  // Across kinds they can share TMEM: CI on map 1 (0x10000..) and RGB565 on map 1 (odd 0x10000).
  EXPECT_TRUE(regions_overlap(texture_cache_region(TexFormat::CI8, false, 1),
                              texture_cache_region(TexFormat::RGB565, false, 1)));
  EXPECT_FALSE(regions_overlap(texture_cache_region(TexFormat::I8, false, 0),
                               texture_cache_region(TexFormat::CI8, false, 1)));
}

TEST(GxTmem, TlutRegionsAreGxInitsAndTheirOffsetsGxInitTlutRegions) {
  for (int n = 0; n < 16; ++n) {
    const TlutRegion r = tlut_region(n);
    EXPECT_EQ(r.tmem_address, 0xC0000u + 0x2000u * static_cast<u32>(n));
    EXPECT_EQ(r.entries, 256);
    // (tmem - 0x80000) >> 9: 0x200 + 16 n.
    EXPECT_EQ(tlut_tmem_offset(r), 0x200u + 16u * static_cast<u32>(n));
    EXPECT_EQ(tlut_region_entries_at(tlut_tmem_offset(r)), 256);
  }
  for (int n = 0; n < 4; ++n) {
    const TlutRegion r = tlut_region(16 + n);
    EXPECT_EQ(r.tmem_address, 0xE0000u + 0x8000u * static_cast<u32>(n));
    EXPECT_EQ(r.entries, 1024);
    EXPECT_EQ(tlut_tmem_offset(r), 0x300u + 64u * static_cast<u32>(n));
    EXPECT_EQ(tlut_region_entries_at(tlut_tmem_offset(r)), 1024);
  }
  EXPECT_EQ(tlut_lines(16), 1);
  EXPECT_EQ(tlut_lines(17), 2);
  EXPECT_EQ(tlut_lines(256), 16);  // GX_TLUT_256 [OGC gx.h GX_TLUT_256 16]
}

TEST(GxTmem, ATextureOccupiesItsBytesUpToItsRegion) {
  EXPECT_EQ(texture_tmem_bytes(1024), 1024u);
  EXPECT_EQ(texture_tmem_bytes(65536), 65536u);
  EXPECT_EQ(texture_tmem_bytes(4u << 20), 65536u);
}

}  // namespace
}  // namespace lt::gx
