// TMEM, the texture unit's 1 MiB of texture memory, as libogc's GX_Init divides it: each map's
// texture cache region (by the texture's format and whether it is mipmapped) and the TLUT
// regions palettes are loaded into (docs/textures.md "TMEM"). The FIFO log loads textures and
// palettes into these regions, and the budget reports what each map occupies of them.
#pragma once

#include <cstddef>

#include "gx/gx_types.h"
#include "gx/texture_format.h"

namespace lt::gx {

// A texture cache region: TMEM addresses of its even and odd halves, each a 32 KiB cache
// (GX_TEXCACHE_32K: every region GX_Init makes) [OGC gx.c GX_InitTexCacheRegion L3149-3191].
struct TexCacheRegion {
  u32 even = 0, odd = 0;
};
inline constexpr size_t kTexCacheHalfBytes = 32 * 1024;
inline constexpr size_t kTexCacheRegionBytes = 2 * kTexCacheHalfBytes;

// The region GX_LoadTexObj takes for map `map` (0..7) on the Wii through libogc's default
// callback [OGC gx.c __GXDefTexRegionCallback L554-571]: colour-indexed and CMPR textures
// texRegion[map], every other format texRegion[map + 8], mipmapped ones texRegion[map + 16]
// (a colour-indexed texture keeps texRegion[map] even mipmapped: the callback returns before
// the mipmap test); GX_Init places them at _gxtexregionaddrtable[map + 0 / 16 / 32] (even) and
// [map + 8 / 24 / 40] (odd) [OGC gx.c L114-127, L1175-1188].
TexCacheRegion texture_cache_region(TexFormat format, bool mipmap, int map);
// TMEM a texture of `texture_bytes` (GX_GetTexBufferSize's rule: texture_format.h level_bytes)
// occupies in its region: all of it up to the region's two 32 KiB caches. A larger texture is
// still drawn, its tiles streamed through the cache from main memory (refetched as they are
// evicted), so it does not stay resident.
std::size_t texture_tmem_bytes(std::size_t texture_bytes);
// Whether two regions share TMEM (either half of one overlapping either half of the other): two
// maps of one draw in such regions evict each other's tiles.
bool regions_overlap(const TexCacheRegion& a, const TexCacheRegion& b);

// GX_TLUT0..GX_TLUT15 (0..15) and GX_BIGTLUT0..3 (16..19) [OGC gx.h L1131-1154]: GX_Init puts
// the 16 small ones, 256 entries each (GX_TLUT_256), at 0xC0000 + (n << 13) and the 4 big ones,
// 1,024 entries (GX_TLUT_1K), at 0xE0000 + (n << 15) [OGC gx.c L1191-1204].
inline constexpr int kTlutNames = 20;
struct TlutRegion {
  u32 tmem_address = 0;  // in TMEM's 1 MiB
  int entries = 0;       // what the region holds
};
TlutRegion tlut_region(int tlut_name);
// The TLUT register's TMEM offset: (address - 0x80000) >> 9, 10 bits, as GX_InitTlutRegion
// stores it and both BP_LOADTLUT1 and the texture's TLUT register carry it [OGC gx.c
// GX_InitTlutRegion L3214-3224]; Dolphin reads the palette at texMem[offset << 9] [DSW
// TextureSampler.cpp SampleMip, `texTlut.tmem_offset << 9`].
u32 tlut_tmem_offset(const TlutRegion& region);
// TMEM lines (32 bytes, 16 entries) of `entries`: BP_LOADTLUT1's count field [DHW BPStructs.cpp
// BPMEM_LOADTLUT1, tmem_line_count * TMEM_LINE_SIZE].
int tlut_lines(int entries);
// The entries of GX_Init's TLUT region at a TLUT register's TMEM offset (256 below the big
// TLUTs' first offset, else 1,024). GX_LoadTlut loads the whole region, whatever the palette's
// entries: its BP_LOADTLUT1 word is the region's tmem_addr_conf, the region's size in lines
// [OGC gx.c GX_InitTlutRegion L3221, GX_LoadTlut L3657].
int tlut_region_entries_at(u32 tmem_offset);

}  // namespace lt::gx
