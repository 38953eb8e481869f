#include "gx/tmem.h"

#include "core/error.h"

namespace lt::gx {

namespace {

// _gxtexregionaddrtable [OGC gx.c L114-127]: rows of 8 maps; rows 0/1 even/odd of
// texRegion[0..7], rows 2/3 of texRegion[8..15], rows 4/5 of texRegion[16..23].
constexpr u32 kRegionAddresses[6][8] = {
    {0x00000, 0x10000, 0x20000, 0x30000, 0x40000, 0x50000, 0x60000, 0x70000},
    {0x08000, 0x18000, 0x28000, 0x38000, 0x48000, 0x58000, 0x68000, 0x78000},
    {0x00000, 0x90000, 0x20000, 0xB0000, 0x40000, 0x98000, 0x60000, 0xB8000},
    {0x80000, 0x10000, 0xA0000, 0x30000, 0x88000, 0x50000, 0xA8000, 0x70000},
    {0x00000, 0x90000, 0x20000, 0xB0000, 0x40000, 0x90000, 0x60000, 0xB0000},
    {0x80000, 0x10000, 0xA0000, 0x30000, 0x80000, 0x50000, 0xA0000, 0x70000}};

}  // namespace

TexCacheRegion texture_cache_region(TexFormat format, bool mipmap, int map) {
  LT_CHECK(map >= 0 && map < kMaxTexMaps, "a texture map is 0..7");
  int group = 1;  // texRegion[map + 8]
  if (is_indexed(format)) {
    group = 0;
  } else {
    if (format == TexFormat::CMPR) group = 0;
    if (mipmap) group = 2;
  }
  const auto m = static_cast<size_t>(map);
  return {kRegionAddresses[2 * group][m], kRegionAddresses[2 * group + 1][m]};
}

std::size_t texture_tmem_bytes(std::size_t texture_bytes) {
  return texture_bytes < kTexCacheRegionBytes ? texture_bytes : kTexCacheRegionBytes;
}

bool regions_overlap(const TexCacheRegion& a, const TexCacheRegion& b) {
  auto halves = [](u32 x, u32 y) {
    return x < y + kTexCacheHalfBytes && y < x + kTexCacheHalfBytes;
  };
  return halves(a.even, b.even) || halves(a.even, b.odd) || halves(a.odd, b.even) ||
         halves(a.odd, b.odd);
}

TlutRegion tlut_region(int n) {
  LT_CHECK(n >= 0 && n < kTlutNames, "a TLUT name is GX_TLUT0..15 or GX_BIGTLUT0..3");
  if (n < 16) return {0xC0000u + (static_cast<u32>(n) << 13), 256};
  return {0xE0000u + (static_cast<u32>(n - 16) << 15), 1024};
}

u32 tlut_tmem_offset(const TlutRegion& region) {
  return ((region.tmem_address - 0x80000u) >> 9) & 0x3ffu;
}

int tlut_lines(int entries) {
  return (entries + 15) / 16;
}

int tlut_region_entries_at(u32 tmem_offset) {
  return tmem_offset < tlut_tmem_offset(tlut_region(16)) ? 256 : 1024;
}

}  // namespace lt::gx
