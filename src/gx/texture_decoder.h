// The texture unit's decoders: one texel of every GX texture format (texture_format.h) as the
// console turns the bytes in memory into TEXC / TEXA, 8 bits a component, the palette of a
// colour-indexed texture (a TLUT) included. Cited per format in texture_decoder.cpp; the
// conventions are in docs/spec/gx-hardware.md §3.4 and docs/textures.md.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

#include "gx/gx_types.h"
#include "gx/texture_format.h"

namespace lt::gx {

// One level of a texture as it sits in memory: GX tile order, padded to whole tiles
// (level_bytes(format, width, height) bytes at least).
struct TextureView {
  TexFormat format = TexFormat::I8;
  int width = 0, height = 0;  // 1..1024
  std::span<const u8> data;
};

// A palette as GX_LoadTlut leaves it in TMEM: 16-bit entries, two bytes each in memory order
// (big-endian, as the CPU stored them), entry k at bytes 2k and 2k + 1.
struct TlutView {
  TlutFormat format = TlutFormat::RGB565;
  std::span<const u8> entries;
  std::size_t size() const { return entries.size() / 2; }
};

// Bit replication of an n-bit field to 8 bits, the high bits repeated into the low ones
// [DHW LookUpTables.h Convert3To8, Convert4To8, Convert5To8, Convert6To8].
constexpr u8 bits3_to_8(int v) {
  return static_cast<u8>((v << 5) | (v << 2) | (v >> 1));
}
constexpr u8 bits4_to_8(int v) {
  return static_cast<u8>((v << 4) | v);
}
constexpr u8 bits5_to_8(int v) {
  return static_cast<u8>((v << 3) | (v >> 2));
}
constexpr u8 bits6_to_8(int v) {
  return static_cast<u8>((v << 2) | (v >> 4));
}

// 16-bit texels and palette entries, the value as a big-endian u16 (its first byte the high one).
Color8 decode_rgb565(u16 value);
Color8 decode_rgb5a3(u16 value);
// IA8: the first byte is alpha, the second intensity.
Color8 decode_ia8(u8 first, u8 second);
// A palette entry of `format`, its two bytes in memory order.
Color8 decode_tlut_entry(TlutFormat format, u8 first, u8 second);

// CMPR's four colours of a block whose two endpoints are c1 and c2 (big-endian RGB565 values,
// the block's first and second u16): c1 > c2 gives c1, c2, (5 c1 + 3 c2) / 8, (3 c1 + 5 c2) / 8
// (the console's 3/8-5/8 blend, not DXT1's thirds); otherwise c1, c2, their average and the
// average again with alpha 0.
std::array<Color8, 4> cmpr_palette(u16 c1, u16 c2);

// Where texel (x, y) of a width-wide level sits: the byte, and for the 4-bit formats whether it
// is the byte's high nibble (even x inside a tile row); for CMPR the 8-byte block holding it.
struct TexelAddress {
  std::size_t byte = 0;
  bool high_nibble = false;
};
TexelAddress texel_address(TexFormat format, int width, int x, int y);

// The texel (x, y), 0 <= x < width, 0 <= y < height, of `texture` decoded to (TEXC, TEXA).
// Colour-indexed formats need `tlut` with an entry for every index they read (LT_CHECK: the
// callers refuse a TLUT too small for its texture's indices); the others ignore it.
Color8 decode_texel(const TextureView& texture, int x, int y, const TlutView* tlut = nullptr);
// Every texel, row-major, row 0 first (the first row in memory).
std::vector<Color8> decode_texture(const TextureView& texture, const TlutView* tlut = nullptr);
// The largest index a colour-indexed level uses (0 for the other formats): a TLUT must hold
// more entries than this.
int largest_index(const TextureView& texture);

}  // namespace lt::gx
