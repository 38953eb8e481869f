// The GX texture decoders (src/gx/texture_decoder.h): every format's bits and tile addressing
// worked out in the test from the hardware rules (docs/spec/gx-hardware.md §3.4), CMPR's two
// modes with hand-computed colours, TLUT lookups, and the four formats the texture unit decodes
// today (gx/texture_unit.h) byte-identical through both.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "gx/texture_decoder.h"
#include "gx/texture_format.h"
#include "gx/texture_unit.h"

namespace lt::gx {
namespace {

TextureView texture_view(TexFormat f, int w, int h, const std::vector<u8>& data) {
  return {f, w, h, std::span<const u8>(data)};
}

TEST(GxTextureFormat, TileSizesAndBytesFollowGXGetTexBufferSize) {
  // A 13x5 texture: I4 8x8 tiles -> 2x1 tiles of 32 bytes; I8 8x4 -> 2x2; RGB565 4x4 -> 4x2;
  // RGBA8 4x4 of 64 bytes -> 4x2; CMPR 8x8 -> 2x1; CI14X2 4x4 -> 4x2.
  EXPECT_EQ(level_bytes(TexFormat::I4, 13, 5), 2u * 1 * 32);
  EXPECT_EQ(level_bytes(TexFormat::CI4, 13, 5), 2u * 1 * 32);
  EXPECT_EQ(level_bytes(TexFormat::I8, 13, 5), 2u * 2 * 32);
  EXPECT_EQ(level_bytes(TexFormat::IA4, 13, 5), 2u * 2 * 32);
  EXPECT_EQ(level_bytes(TexFormat::CI8, 13, 5), 2u * 2 * 32);
  EXPECT_EQ(level_bytes(TexFormat::RGB565, 13, 5), 4u * 2 * 32);
  EXPECT_EQ(level_bytes(TexFormat::CI14X2, 13, 5), 4u * 2 * 32);
  EXPECT_EQ(level_bytes(TexFormat::RGBA8, 13, 5), 4u * 2 * 64);
  EXPECT_EQ(level_bytes(TexFormat::CMPR, 13, 5), 2u * 1 * 32);
  // A whole texture's bits a texel: 64x64 at 4 bits is 2048 bytes, at 32 bits 16384.
  EXPECT_EQ(level_bytes(TexFormat::CMPR, 64, 64), 2048u);
  EXPECT_EQ(level_bytes(TexFormat::RGBA8, 64, 64), 16384u);
  // Mip chain 8x2 -> 4x1 -> 2x1 -> 1x1 in I8: one 8x4 tile each, 4 levels.
  EXPECT_EQ(full_mip_levels(8, 2), 4);
  EXPECT_EQ(mip_chain_bytes(TexFormat::I8, 8, 2, 4), 4u * 32);
  EXPECT_EQ(mip_chain_bytes(TexFormat::RGB565, 16, 16, 3), 512u + 128 + 32);
}

TEST(GxTextureFormat, NamesAndNumbersRoundTrip) {
  for (TexFormat f : kAllTexFormats) {
    EXPECT_EQ(tex_format_from_name(format_info(f).name), f);
    EXPECT_EQ(tex_format_from_number(static_cast<int>(f)), f);
  }
  EXPECT_EQ(tex_format_from_name("GX_TF_CI14"), TexFormat::CI14X2);
  EXPECT_EQ(tex_format_from_name("cmpr"), TexFormat::CMPR);
  EXPECT_FALSE(tex_format_from_name("RGB888").has_value());
  EXPECT_FALSE(tex_format_from_number(7).has_value());
  EXPECT_EQ(tlut_format_from_name("GX_TL_RGB5A3"), TlutFormat::RGB5A3);
}

TEST(GxTextureDecoder, BitExpansionsReplicateTheHighBits) {
  // Spot values worked by hand: 3 bits 0b101 -> 101 101 10 = 182; 4 bits v * 17; 5 bits
  // 0b00011 -> 00011 000 = 24; 0b10000 -> 10000 100 = 132; 6 bits 0b100000 -> 100000 10 = 130.
  EXPECT_EQ(bits3_to_8(5), 182);
  EXPECT_EQ(bits3_to_8(7), 255);
  for (int v = 0; v < 16; ++v) EXPECT_EQ(bits4_to_8(v), v * 17);
  EXPECT_EQ(bits5_to_8(3), 24);
  EXPECT_EQ(bits5_to_8(16), 132);
  EXPECT_EQ(bits5_to_8(31), 255);
  EXPECT_EQ(bits6_to_8(32), 130);
  EXPECT_EQ(bits6_to_8(1), 4);
  EXPECT_EQ(bits6_to_8(63), 255);
}

// Texel (x, y)'s index in its tile and the tile's index, for tiles of tw x th texels: the
// closed form of §3.4, written here apart from the decoder's code.
int tile_index(int w, int tw, int th, int x, int y) {
  const int across = (w + tw - 1) / tw;
  return (y / th) * across + x / tw;
}

TEST(GxTextureDecoder, I4AndIA4UnpackNibbles) {
  const int w = 16, h = 8;  // I4: two 8x8 tiles; IA4: two 8x4 tiles across, two down
  std::vector<u8> i4(level_bytes(TexFormat::I4, w, h), 0), ia4(level_bytes(TexFormat::IA4, w, h));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int v = (x * 3 + y * 5) & 15;
      const int byte = tile_index(w, 8, 8, x, y) * 32 + ((y % 8) * 8 + x % 8) / 2;
      i4[static_cast<size_t>(byte)] |= static_cast<u8>(x % 2 == 0 ? v << 4 : v);
      const int alpha = (x + 7 * y) & 15;
      ia4[static_cast<size_t>(tile_index(w, 8, 4, x, y) * 32 + (y % 4) * 8 + x % 8)] =
          static_cast<u8>(alpha << 4 | v);
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const u8 i = static_cast<u8>(((x * 3 + y * 5) & 15) * 17);
      const u8 a = static_cast<u8>(((x + 7 * y) & 15) * 17);
      EXPECT_EQ(decode_texel(texture_view(TexFormat::I4, w, h, i4), x, y), (Color8{i, i, i, i}));
      EXPECT_EQ(decode_texel(texture_view(TexFormat::IA4, w, h, ia4), x, y), (Color8{i, i, i, a}));
    }
}

TEST(GxTextureDecoder, RGB5A3PicksItsModePerTexel) {
  // A 4x4 tile: texel 0 opaque 555 (1, 10101, 00011, 11111), texel 1 a3 r4 g4 b4 (0, 101, 1100,
  // 0011, 1111).
  std::vector<u8> d(32, 0);
  d[0] = 0b1'10101'00;
  d[1] = 0b011'11111;
  d[2] = 0b0'101'1100;
  d[3] = 0b0011'1111;
  const TextureView t = texture_view(TexFormat::RGB5A3, 4, 4, d);
  EXPECT_EQ(decode_texel(t, 0, 0), (Color8{173, 24, 255, 255}));  // 10101 -> 10101101 = 173
  EXPECT_EQ(decode_texel(t, 1, 0), (Color8{204, 51, 255, 182}));  // 12*17, 3*17, 15*17; a 5
  EXPECT_EQ(decode_texel(t, 2, 0), (Color8{0, 0, 0, 0}));         // all zero: transparent black
}

TEST(GxTextureDecoder, ColourIndexedTexelsLookUpTheirTlut) {
  // TLUT of 16 RGB5A3 entries (entry k = opaque 555 grey k), one IA8 TLUT (alpha first).
  std::vector<u8> rgb5a3(16 * 2), ia8(16 * 2);
  for (int k = 0; k < 16; ++k) {
    const int v = 0x8000 | k << 10 | k << 5 | k;
    rgb5a3[2 * k] = static_cast<u8>(v >> 8);
    rgb5a3[2 * k + 1] = static_cast<u8>(v);
    ia8[2 * k] = static_cast<u8>(255 - k);  // alpha
    ia8[2 * k + 1] = static_cast<u8>(k * 10);
  }
  // CI4 8x8: texel (x, y) holds index (x + y) & 15.
  std::vector<u8> ci4(32, 0);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      ci4[static_cast<size_t>((y * 8 + x) / 2)] |=
          static_cast<u8>(x % 2 == 0 ? ((x + y) & 15) << 4 : (x + y) & 15);
  const TlutView t565{TlutFormat::RGB5A3, rgb5a3}, tia{TlutFormat::IA8, ia8};
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      const int k = (x + y) & 15;
      const u8 g = bits5_to_8(k);
      EXPECT_EQ(decode_texel(texture_view(TexFormat::CI4, 8, 8, ci4), x, y, &t565),
                (Color8{g, g, g, 255}));
      const u8 i = static_cast<u8>(k * 10);
      EXPECT_EQ(decode_texel(texture_view(TexFormat::CI4, 8, 8, ci4), x, y, &tia),
                (Color8{i, i, i, static_cast<u8>(255 - k)}));
    }
  // CI8 8x4: byte per texel; CI14X2 4x4: the big-endian u16's low 14 bits, the top two ignored.
  std::vector<u8> ci8(32, 0), ci14(32, 0), big(16384 * 2, 0);
  ci8[9] = 200;               // texel (1, 1)
  ci14[2 * 5] = 0xC0 | 0x3F;  // texel (1, 1): 0xFFFE & 0x3FFF = 0x3FFE
  ci14[2 * 5 + 1] = 0xFE;
  std::vector<u8> tl256(256 * 2, 0);
  tl256[400] = 0xF8;  // entry 200 = RGB565 pure red
  big[2 * 0x3FFE] = 0x00;
  big[2 * 0x3FFE + 1] = 0x1F;  // entry 0x3FFE = RGB565 pure blue
  const TlutView tl{TlutFormat::RGB565, tl256}, tb{TlutFormat::RGB565, big};
  EXPECT_EQ(decode_texel(texture_view(TexFormat::CI8, 8, 4, ci8), 1, 1, &tl),
            (Color8{255, 0, 0, 255}));
  EXPECT_EQ(decode_texel(texture_view(TexFormat::CI14X2, 4, 4, ci14), 1, 1, &tb),
            (Color8{0, 0, 255, 255}));
  EXPECT_EQ(largest_index(texture_view(TexFormat::CI14X2, 4, 4, ci14)), 0x3FFE);
  // CI14X2 8x8: four 4x4 tiles of 32 bytes, two a row; texel (5, 6) is tile 3 (byte 96), tile
  // texel (1, 2), 2 * (2 * 4 + 1) = 18 bytes in: bytes 114-115. 0x4321 & 0x3FFF = 801, an entry
  // of pure green (0x07E0); read little-endian it would be 0x2143, a black entry.
  std::vector<u8> ci14_tiles(128, 0);
  ci14_tiles[114] = 0x43, ci14_tiles[115] = 0x21;
  big[2 * 801] = 0x07, big[2 * 801 + 1] = 0xE0;
  EXPECT_EQ(decode_texel(texture_view(TexFormat::CI14X2, 8, 8, ci14_tiles), 5, 6, &tb),
            (Color8{0, 255, 0, 255}));
  EXPECT_EQ(largest_index(texture_view(TexFormat::CI14X2, 8, 8, ci14_tiles)), 801);
  EXPECT_EQ(largest_index(texture_view(TexFormat::CI4, 8, 8, ci4)), 14);
}

// One CMPR block: endpoints c1, c2 big-endian, then one byte a row, texel 0 in the top bits.
void put_cmpr_block(std::vector<u8>& d, size_t at, u16 c1, u16 c2, const u8 rows[4]) {
  d[at] = static_cast<u8>(c1 >> 8);
  d[at + 1] = static_cast<u8>(c1);
  d[at + 2] = static_cast<u8>(c2 >> 8);
  d[at + 3] = static_cast<u8>(c2);
  for (int r = 0; r < 4; ++r) d[at + 4 + static_cast<size_t>(r)] = rows[r];
}

TEST(GxTextureDecoder, CmprBlendsAtThreeAndFiveEighths) {
  // c1 = pure red (0xF800) > c2 = pure blue (0x001F): colour 2 = 5/8 red + 3/8 blue,
  // (255*5 >> 3, 0, 255*3 >> 3) = (159, 0, 95); colour 3 = (95, 0, 159). DXT1's thirds would
  // give 170 and 85.
  std::vector<u8> d(32, 0);
  const u8 rows[4] = {0b00'01'10'11, 0b11'10'01'00, 0, 0};
  put_cmpr_block(d, 0, 0xF800, 0x001F, rows);
  const TextureView t = texture_view(TexFormat::CMPR, 8, 8, d);
  EXPECT_EQ(decode_texel(t, 0, 0), (Color8{255, 0, 0, 255}));
  EXPECT_EQ(decode_texel(t, 1, 0), (Color8{0, 0, 255, 255}));
  EXPECT_EQ(decode_texel(t, 2, 0), (Color8{159, 0, 95, 255}));
  EXPECT_EQ(decode_texel(t, 3, 0), (Color8{95, 0, 159, 255}));
  EXPECT_EQ(decode_texel(t, 0, 1), (Color8{95, 0, 159, 255}));
  EXPECT_EQ(decode_texel(t, 3, 1), (Color8{255, 0, 0, 255}));
}

TEST(GxTextureDecoder, CmprThreeColourModeAveragesAndMakesTransparent) {
  // c1 = 0x0821 (r 1, g 1, b 1 -> 8, 4, 8) <= c2 = 0xFFFF (white): colour 2 = floor average
  // ((8+255)/2, (4+255)/2, (8+255)/2) = (131, 129, 131) opaque; colour 3 the same, alpha 0.
  std::vector<u8> d(32, 0);
  const u8 rows[4] = {0b10'11'00'01, 0, 0, 0};
  // Put the block in the tile's bottom-right quarter (its fourth 8 bytes): texels (4..7, 4..7).
  put_cmpr_block(d, 24, 0x0821, 0xFFFF, rows);
  const TextureView t = texture_view(TexFormat::CMPR, 8, 8, d);
  EXPECT_EQ(decode_texel(t, 4, 4), (Color8{131, 129, 131, 255}));
  EXPECT_EQ(decode_texel(t, 5, 4), (Color8{131, 129, 131, 0}));
  EXPECT_EQ(decode_texel(t, 6, 4), (Color8{8, 4, 8, 255}));
  EXPECT_EQ(decode_texel(t, 7, 4), (Color8{255, 255, 255, 255}));
  // The other three quarters are all-zero blocks: c1 = c2 = 0, three-colour mode, index 0.
  EXPECT_EQ(decode_texel(t, 0, 0), (Color8{0, 0, 0, 255}));
}

TEST(GxTextureDecoder, CmprTilesAreEightByEightOfFourBlocks) {
  // A 16x8 texture: two tiles; block k of the whole texture (tile-major, then TL TR BL BR) has
  // c1 = c2 + 1 > c2 = k * 0x0800 (red k), every index 1 (c2): texel (x, y) reads red of its block.
  std::vector<u8> d(64, 0);
  const u8 ones[4] = {0x55, 0x55, 0x55, 0x55};
  for (int k = 0; k < 8; ++k)
    put_cmpr_block(d, static_cast<size_t>(k) * 8, static_cast<u16>(k * 0x0800 + 1),
                   static_cast<u16>(k * 0x0800), ones);
  const TextureView t = texture_view(TexFormat::CMPR, 16, 8, d);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) {
      const int block = (x / 8) * 4 + ((y % 8) / 4) * 2 + (x % 8) / 4;
      EXPECT_EQ(decode_texel(t, x, y).r, bits5_to_8(block)) << x << "," << y;
    }
}

TEST(GxTextureDecoder, TheFourFormatsOfTodaysTextureUnitDecodeByteIdentically) {
  std::mt19937 rng(47);
  const struct {
    TexFormat format;
    u8 number;
  } formats[] = {{TexFormat::I8, kTexFormatI8},
                 {TexFormat::IA8, kTexFormatIA8},
                 {TexFormat::RGB565, kTexFormatRGB565},
                 {TexFormat::RGBA8, kTexFormatRGBA8}};
  for (const auto& f : formats) {
    for (const auto& [w, h] : {std::pair{1, 1}, {5, 3}, {13, 9}, {64, 16}, {33, 7}}) {
      TextureObject old;
      old.format = f.number;
      old.width = w;
      old.height = h;
      old.data.resize(tiled_size(f.number, w, h));
      for (u8& b : old.data) b = static_cast<u8>(rng());
      const TextureView t = texture_view(f.format, w, h, old.data);
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          ASSERT_EQ(decode_texel(t, x, y), texel_at(old, x, y))
              << format_info(f.format).name << " " << w << "x" << h << " at " << x << "," << y;
    }
  }
}

TEST(GxTextureDecoder, TheTextureUnitSamplesEveryOtherFormatThroughIt) {
  // I4 8x8: texel (0, 0) = 3 (51), (1, 0) = 12 (204). Bilinear halfway between their centres
  // (u = 128, v = 64: fs = 64, ft = 0) is (51 * 64 + 204 * 64) >> 7 = 127 in every component.
  TextureObject i4;
  i4.format = static_cast<u8>(TexFormat::I4);
  i4.width = i4.height = 8;
  i4.data.assign(32, 0);
  i4.data[0] = 0x3C;
  EXPECT_EQ(sample_texture(i4, 128, 64), (Color8{127, 127, 127, 127}));
  // CI8 8x4 with an RGB5A3 TLUT: nearest sampling at each texel's centre is the decoder's texel.
  TextureObject ci8;
  ci8.format = static_cast<u8>(TexFormat::CI8);
  ci8.width = 8;
  ci8.height = 4;
  ci8.linear = false;
  ci8.data.resize(32);
  for (size_t k = 0; k < 32; ++k) ci8.data[k] = static_cast<u8>(k % 3);
  ci8.tlut_format = static_cast<u8>(TlutFormat::RGB5A3);
  ci8.tlut = {0x80, 0x1F, 0x7F, 0x00, 0x30, 0xF0};  // opaque blue; a 7 r15; a 3 g15
  const TlutView tlut{TlutFormat::RGB5A3, ci8.tlut};
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 8; ++x)
      EXPECT_EQ(sample_texture(ci8, x * 128 + 64, y * 128 + 64),
                decode_texel(texture_view(TexFormat::CI8, 8, 4, ci8.data), x, y, &tlut));
  EXPECT_EQ(sample_texture(ci8, 64, 64), (Color8{0, 0, 255, 255}));
  EXPECT_EQ(tiled_size(static_cast<u8>(TexFormat::CMPR), 13, 5), 64u);
}

}  // namespace
}  // namespace lt::gx
