// Every GX texture format decoded as the console decodes it (texture_decoder.h). The rules are
// Dolphin's [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel] (the per-texel decoder its
// software renderer samples through), read at jordan-woyak/dolphin @ 65ec7b5 (docs/spec/
// gx-hardware.md §0), CMPR's blend checked on a console by [HWT gxtest/cmpr.cpp @ 630e91b].
#include "gx/texture_decoder.h"

#include <algorithm>

#include "core/error.h"

namespace lt::gx {

Color8 decode_rgb565(u16 value) {
  // r in bits 15..11, g 10..5, b 4..0, alpha 255 [DHW DecodePixel_RGB565].
  return {bits5_to_8((value >> 11) & 0x1f), bits6_to_8((value >> 5) & 0x3f),
          bits5_to_8(value & 0x1f), 255};
}

Color8 decode_rgb5a3(u16 value) {
  // Bit 15 picks the mode per texel [DHW DecodePixel_RGB5A3]: set, an opaque RGB555 (r 14..10,
  // g 9..5, b 4..0); clear, a3 r4 g4 b4 (a in 14..12).
  if ((value & 0x8000) != 0)
    return {bits5_to_8((value >> 10) & 0x1f), bits5_to_8((value >> 5) & 0x1f),
            bits5_to_8(value & 0x1f), 255};
  return {bits4_to_8((value >> 8) & 0xf), bits4_to_8((value >> 4) & 0xf), bits4_to_8(value & 0xf),
          bits3_to_8((value >> 12) & 0x7)};
}

Color8 decode_ia8(u8 first, u8 second) {
  // Dolphin reads the two bytes as a little-endian u16 and takes `a = val & 0xFF` (the first
  // byte), `i = val >> 8` (the second) [DHW DecodePixel_IA8].
  return {second, second, second, first};
}

Color8 decode_tlut_entry(TlutFormat format, u8 first, u8 second) {
  // An IA8 entry is read as an IA8 texel; RGB565 and RGB5A3 entries are byte-swapped to their
  // big-endian value first [DHW DecodePixel_Paletted].
  const u16 value = static_cast<u16>((first << 8) | second);
  switch (format) {
    case TlutFormat::IA8:
      return decode_ia8(first, second);
    case TlutFormat::RGB565:
      return decode_rgb565(value);
    case TlutFormat::RGB5A3:
      return decode_rgb5a3(value);
  }
  LT_CHECK(false, "not a GX TLUT format");
  return {};
}

std::array<Color8, 4> cmpr_palette(u16 c1, u16 c2) {
  const Color8 a = decode_rgb565(c1), b = decode_rgb565(c2);
  std::array<Color8, 4> p{a, b, {}, {}};
  for (int c = 0; c < 3; ++c) {
    if (c1 > c2) {
      // 3/8 and 5/8, truncated: `DXTBlend(v1, v2) = (v1 * 3 + v2 * 5) >> 3`, colour 2 =
      // DXTBlend(c2, c1), colour 3 = DXTBlend(c1, c2) [DHW TextureDecoder_Util.h DXTBlend]
      // [HWT gxtest/cmpr.cpp @ 630e91b L60-63, L128-135: compared with a console's texels]
      // [PR#3897] [PR#4656].
      p[2][c] = static_cast<u8>((a[c] * 5 + b[c] * 3) >> 3);
      p[3][c] = static_cast<u8>((a[c] * 3 + b[c] * 5) >> 3);
    } else {
      // The floor of the average, twice, the second transparent (DXT1's colour 3 would be black)
      // [DHW TexDecoder_DecodeTexel case CMPR, colorSel 6 and 7] [PR#4512]
      // [HWT gxtest/cmpr.cpp @ 630e91b L137-143]. The test compares r, g and b only: alpha 0 is
      // Dolphin's model (docs/spec/gx-hardware.md §3.4).
      p[2][c] = p[3][c] = static_cast<u8>((a[c] + b[c]) / 2);
    }
  }
  p[2].a = 255;
  p[3].a = c1 > c2 ? 255 : 0;
  return p;
}

TexelAddress texel_address(TexFormat format, int width, int x, int y) {
  // Tiles row-major, ceil(W / tile width) of them a row; Dolphin writes the count as
  // ((W - 1) >> 3) + 1 or ((W - 1) >> 2) + 1 (its `imageWidth` is the size register, W - 1)
  // [DHW TexDecoder_DecodeTexel, every case's widthBlks].
  const TexFormatInfo& info = format_info(format);
  const std::size_t across =
      static_cast<std::size_t>((width + info.tile_width - 1) / info.tile_width);
  const std::size_t tile = static_cast<std::size_t>(y / info.tile_height) * across +
                           static_cast<std::size_t>(x / info.tile_width);
  const std::size_t base = tile * static_cast<std::size_t>(info.tile_bytes);
  const int tx = x % info.tile_width, ty = y % info.tile_height;
  switch (format) {
    case TexFormat::CMPR:
      // Four 4x4 blocks of 8 bytes, top-left, top-right, bottom-left, bottom-right [DHW case
      // CMPR: `blkOff = (blkT << 1) + blkS`, `offset = (base + blkOff) << 3`].
      return {base + static_cast<std::size_t>(((ty >> 2) * 2 + (tx >> 2)) * 8), false};
    default:
      break;
  }
  const int in_tile = ty * info.tile_width + tx;
  if (info.bits_per_texel == 4)  // I4, CI4: the even texel in the high nibble [DHW `rs`]
    return {base + static_cast<std::size_t>(in_tile >> 1), (in_tile & 1) == 0};
  // 8 bits: one byte a texel; 16 bits and RGBA8's halves: two.
  const int bytes = info.bits_per_texel == 8 ? 1 : 2;
  return {base + static_cast<std::size_t>(in_tile * bytes), false};
}

namespace {

u16 big_endian16(const u8* p) {
  return static_cast<u16>((p[0] << 8) | p[1]);
}

Color8 tlut_lookup(const TlutView* tlut, int index) {
  LT_CHECK(tlut != nullptr, "a colour-indexed texture needs its TLUT");
  LT_CHECK(static_cast<std::size_t>(index) < tlut->size(),
           "TLUT too small for the texture's index");
  return decode_tlut_entry(tlut->format, tlut->entries[2 * static_cast<std::size_t>(index)],
                           tlut->entries[2 * static_cast<std::size_t>(index) + 1]);
}

// The texel's index (colour-indexed formats) or its packed value before decoding.
int raw_index(const TextureView& t, const TexelAddress& at) {
  const u8* d = t.data.data() + at.byte;
  switch (t.format) {
    case TexFormat::CI4:
      return at.high_nibble ? d[0] >> 4 : d[0] & 0xf;
    case TexFormat::CI8:
      return d[0];
    // The big-endian u16's low 14 bits [DHW case C14X2: `swap16(...) & 0x3FFF`].
    case TexFormat::CI14X2:
      return big_endian16(d) & 0x3fff;
    default:
      return 0;
  }
}

void check_view(const TextureView& t) {
  LT_CHECK(
      t.width >= 1 && t.width <= kMaxTextureSize && t.height >= 1 && t.height <= kMaxTextureSize,
      "texture size must be 1..1024 per side");
  LT_CHECK(t.data.size() >= level_bytes(t.format, t.width, t.height),
           "texture data must hold the whole tiles of its size");
}

Color8 decode_unchecked(const TextureView& t, int x, int y, const TlutView* tlut) {
  const TexelAddress at = texel_address(t.format, t.width, x, y);
  const u8* d = t.data.data() + at.byte;
  switch (t.format) {
    case TexFormat::I4: {  // one nibble replicated everywhere [DHW case I4]
      const u8 i = bits4_to_8(at.high_nibble ? d[0] >> 4 : d[0] & 0xf);
      return {i, i, i, i};
    }
    case TexFormat::I8:
      return {d[0], d[0], d[0], d[0]};
    case TexFormat::IA4: {  // alpha the high nibble, intensity the low [DHW case IA4]
      const u8 i = bits4_to_8(d[0] & 0xf);
      return {i, i, i, bits4_to_8(d[0] >> 4)};
    }
    case TexFormat::IA8:
      return decode_ia8(d[0], d[1]);
    case TexFormat::RGB565:
      return decode_rgb565(big_endian16(d));
    case TexFormat::RGB5A3:
      return decode_rgb5a3(big_endian16(d));
    case TexFormat::RGBA8:
      // A and R in the tile's first 32 bytes, G and B at the same place in the next 32 [DHW case
      // RGBA8: `dst[3] = offset, dst[0] = offset + 1, dst[1] = offset + 32, dst[2] = offset + 33`].
      return {d[1], d[32], d[33], d[0]};
    case TexFormat::CI4:
    case TexFormat::CI8:
    case TexFormat::CI14X2:
      return tlut_lookup(tlut, raw_index(t, at));
    case TexFormat::CMPR: {
      // Endpoints big-endian; one byte a row of the block, texel 0 in the top two bits
      // [DHW case CMPR: `lines[tt]`, `rs = 6 - (ss << 1)`].
      const int row = d[4 + (y & 3)];
      const int select = (row >> (6 - 2 * (x & 3))) & 3;
      return cmpr_palette(big_endian16(d), big_endian16(d + 2))[static_cast<std::size_t>(select)];
    }
  }
  LT_CHECK(false, "not a GX texture format");
  return {};
}

}  // namespace

Color8 decode_texel(const TextureView& texture, int x, int y, const TlutView* tlut) {
  check_view(texture);
  LT_CHECK(x >= 0 && x < texture.width && y >= 0 && y < texture.height, "texel out of range");
  return decode_unchecked(texture, x, y, tlut);
}

std::vector<Color8> decode_texture(const TextureView& texture, const TlutView* tlut) {
  check_view(texture);
  std::vector<Color8> out;
  out.reserve(static_cast<std::size_t>(texture.width) * static_cast<std::size_t>(texture.height));
  for (int y = 0; y < texture.height; ++y)
    for (int x = 0; x < texture.width; ++x) out.push_back(decode_unchecked(texture, x, y, tlut));
  return out;
}

int largest_index(const TextureView& texture) {
  check_view(texture);
  if (!is_indexed(texture.format)) return 0;
  int largest = 0;
  for (int y = 0; y < texture.height; ++y)
    for (int x = 0; x < texture.width; ++x)
      largest =
          std::max(largest, raw_index(texture, texel_address(texture.format, texture.width, x, y)));
  return largest;
}

}  // namespace lt::gx
