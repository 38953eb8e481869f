// `:map=FMT` (gx_variant.h): the parser's values and their canonical spelling, which maps each
// format applies to, and the texels each format stores for a map, from the hardware's expansion
// rules (4 bits: q * 17; 5 bits: q << 3 | q >> 2) rather than from the encoder's output.
#include <gtest/gtest.h>

#include <cstdlib>

#include "core/error.h"
#include "gx/texture_encoder.h"
#include "gx/texture_unit.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/thickness_texture.h"

namespace lt::gx {
namespace {

std::vector<float> grey_of(const std::vector<int>& bytes) {
  std::vector<float> out;
  for (int b : bytes)
    for (int c = 0; c < 3; ++c) out.push_back(static_cast<float>(b / 255.0));
  return out;
}

// The nearest n-bit field's expansion to the 8-bit k, found by trying every field.
int nearest_expansion(int k, int bits) {
  int best = 0;
  for (int q = 0; q < (1 << bits); ++q) {
    const int e = bits == 4 ? q * 17 : (q << (8 - bits)) | (q >> (2 * bits - 8));
    if (std::abs(e - k) < std::abs(best - k)) best = e;
  }
  return best;
}

TEST(GxMapFormat, ParsesEveryFormatAndSpellsTheDefaultsAway) {
  for (const char* name : {"rgb565", "rgb5a3", "cmpr", "ia8", "ia4", "i4", "ci4", "ci8"}) {
    const GxVariant v = parse_gx_variant(std::string("t=vertex:map=") + name);
    ASSERT_TRUE(v.map_format) << name;
    EXPECT_EQ(to_string(v), std::string("t=vertex:map=") + name);
    EXPECT_EQ(parse_gx_variant(to_string(v)), v) << name;
  }
  // rgba8 and i8 are the defaults: the same variant as no :map= at all.
  EXPECT_EQ(parse_gx_variant("t=vertex:map=rgba8"), GxVariant{});
  EXPECT_EQ(parse_gx_variant("t=vertex:map=i8"), GxVariant{});
  // CI14X2 is not a map format (gx_variant.h: its palette fits no TLUT region of GX_Init's).
  EXPECT_THROW(parse_gx_variant("t=vertex:map=ci14x2"), InputError);
  EXPECT_THROW(parse_gx_variant("t=vertex:map=ci14"), InputError);
  EXPECT_THROW(parse_gx_variant("t=vertex:map=RGB565"), InputError);
}

TEST(GxMapFormat, AColourFormatIsForColourMapsAGreyOneForGreyMaps) {
  const GxVariant rgb565 = parse_gx_variant("t=vertex:map=rgb565");
  EXPECT_EQ(map_texture_format(rgb565, false), TexFormat::RGB565);
  EXPECT_EQ(map_texture_format(rgb565, true), TexFormat::I8);  // as :map=rgb565 always was
  const GxVariant i4 = parse_gx_variant("t=vertex:map=i4");
  EXPECT_EQ(map_texture_format(i4, true), TexFormat::I4);
  EXPECT_EQ(map_texture_format(i4, false), TexFormat::RGBA8);
  EXPECT_EQ(map_texture_format(GxVariant{}, true), TexFormat::I8);
  EXPECT_EQ(map_texture_format(GxVariant{}, false), TexFormat::RGBA8);
  // A colour-indexed format takes both kinds; the TLUT's format follows the map.
  const GxVariant ci8 = parse_gx_variant("t=vertex:map=ci8");
  EXPECT_EQ(map_texture_format(ci8, true), TexFormat::CI8);
  EXPECT_EQ(map_texture_format(ci8, false), TexFormat::CI8);
  EXPECT_EQ(map_tlut_format(true), TlutFormat::IA8);
  EXPECT_EQ(map_tlut_format(false), TlutFormat::RGB565);
}

// A map of no more distinct texels than the format has entries is exact through its palette:
// a grey one in IA8 entries (8-bit intensity, alpha 255), a colour one whose texels RGB565 holds
// exactly in RGB565 entries; texel_at reads each index through the TLUT as the hardware does.
TEST(GxMapFormat, ColourIndexedMapsOfFewTexelsAreExactThroughTheirTlut) {
  const std::vector<int> k{0, 100, 200, 255, 8, 9, 128, 247, 100, 0, 37, 200};
  for (TexFormat f : {TexFormat::CI4, TexFormat::CI8}) {
    const ThicknessTexture tt = thickness_texture(12, 1, grey_of(k), f, TlutFormat::IA8);
    EXPECT_EQ(tt.format_name, std::string("GX_TF_") + format_info(f).name);
    EXPECT_EQ(tt.texture.data.size(), level_bytes(f, 12, 1));
    EXPECT_EQ(tt.texture.tlut_format, static_cast<u8>(TlutFormat::IA8));
    EXPECT_EQ(tt.texture.tlut.size(), 2u * 9);  // nine distinct intensities, one entry each
    for (int x = 0; x < 12; ++x) {
      const u8 i = static_cast<u8>(k[static_cast<size_t>(x)]);
      EXPECT_EQ(texel_at(tt.texture, x, 0), (Color8{i, i, i, 255})) << format_info(f).name << x;
    }
  }
  // Colours of 5/6/5 fields, each expanded by bit replication: exact in RGB565 entries.
  const std::vector<float> rgb{1, 0, 0, 0, 1, 0, 0, 0, 1, 132 / 255.0f, 130 / 255.0f, 132 / 255.0f};
  const ThicknessTexture tt = thickness_texture(4, 1, rgb, TexFormat::CI8, TlutFormat::RGB565);
  EXPECT_EQ(tt.texture.tlut_format, static_cast<u8>(TlutFormat::RGB565));
  EXPECT_EQ(tt.texture.tlut.size(), 2u * 4);
  const Color8 want[4] = {
      {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {132, 130, 132, 255}};
  for (int x = 0; x < 4; ++x) EXPECT_EQ(texel_at(tt.texture, x, 0), want[x]) << x;
}

TEST(GxMapFormat, GreyFormatsHoldTheNearestIntensityTheirBitsAllow) {
  const std::vector<int> k{0, 100, 200, 255, 8, 9, 128, 247};
  for (TexFormat f : {TexFormat::I4, TexFormat::IA4, TexFormat::IA8}) {
    const ThicknessTexture tt = thickness_texture(8, 1, grey_of(k), f);
    EXPECT_EQ(tt.texture.format, static_cast<u8>(f));
    EXPECT_EQ(tt.format_name, std::string("GX_TF_") + format_info(f).name);
    EXPECT_EQ(tt.texture.data.size(), level_bytes(f, 8, 1));
    const int bits = f == TexFormat::IA8 ? 8 : 4;
    for (int x = 0; x < 8; ++x) {
      const Color8 t = texel_at(tt.texture, x, 0);
      const u8 want = static_cast<u8>(bits == 8 ? k[x] : nearest_expansion(k[x], 4));
      // I4's alpha is its intensity [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel, case
      // I4]; an IA format's is the stored alpha, 255 (IA4: 15 expanded).
      const u8 alpha = f == TexFormat::I4 ? want : 255;
      EXPECT_EQ(t, (Color8{want, want, want, alpha})) << format_info(f).name << " texel " << x;
    }
  }
}

TEST(GxMapFormat, Rgb5a3IsOpaqueRgb555) {
  const std::vector<float> rgb{0.2f, 1.0f, 0.0f, 100 / 255.0f, 200 / 255.0f, 7 / 255.0f};
  const ThicknessTexture tt = thickness_texture(2, 1, rgb, TexFormat::RGB5A3);
  EXPECT_EQ(tt.format_name, "GX_TF_RGB5A3");
  EXPECT_EQ(texel_at(tt.texture, 0, 0),
            (Color8{static_cast<u8>(nearest_expansion(51, 5)), 255, 0, 255}));
  EXPECT_EQ(texel_at(tt.texture, 1, 0), (Color8{static_cast<u8>(nearest_expansion(100, 5)),
                                                static_cast<u8>(nearest_expansion(200, 5)),
                                                static_cast<u8>(nearest_expansion(7, 5)), 255}));
}

TEST(GxMapFormat, CmprKeepsABlockOfTwoRgb565ColoursExactly) {
  // Two colours that RGB565 holds exactly: the best block has them as its endpoints.
  const std::vector<float> rgb{0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1};  // green, magenta, ...
  const ThicknessTexture tt = thickness_texture(4, 1, rgb, TexFormat::CMPR);
  EXPECT_EQ(tt.format_name, "GX_TF_CMPR");
  EXPECT_EQ(tt.texture.data.size(), 32u);  // one 8x8 tile
  for (int x = 0; x < 4; ++x)
    EXPECT_EQ(texel_at(tt.texture, x, 0),
              x % 2 ? (Color8{255, 0, 255, 255}) : (Color8{0, 255, 0, 255}))
        << x;
}

// The formats the frames had before :map=FMT keep their own loop (thickness_texture.cpp): for
// an 8-bit map RGBA8 and I8 are the tree's encoder's bytes, and RGB565 (encoded from the float
// texel) is as near as the encoder's field in every component. Not always the same field: at
// a tie (k = 4: fields 0 and 1 expand to 0 and 8) the encoder takes the lower, while the float
// k / 255 * 255 can land a hair above k and take the upper (docs/textures.md).
TEST(GxMapFormat, TheFormatsOfEarlierFramesMatchTheTreesEncoder) {
  std::vector<float> rgb;
  Rgba8Image image{16, 4, {}};
  for (int i = 0; i < 64; ++i) {
    const Color8 c{static_cast<u8>(i * 4), static_cast<u8>(255 - i * 3),
                   static_cast<u8>(i * 37 % 256), 255};
    image.texels.push_back(c);
    for (int ch = 0; ch < 3; ++ch) rgb.push_back(static_cast<float>(c[ch] / 255.0));
  }
  EXPECT_EQ(thickness_texture(16, 4, rgb, TexFormat::RGBA8).texture.data,
            encode_level(image, TexFormat::RGBA8, EncodeOptions{}).data);
  TextureObject encoders = thickness_texture(16, 4, rgb, TexFormat::RGB565).texture;
  const TextureObject ours = encoders;
  encoders.data = encode_level(image, TexFormat::RGB565, EncodeOptions{}).data;
  for (int i = 0; i < 64; ++i) {
    const Color8 a = texel_at(ours, i % 16, i / 16), b = texel_at(encoders, i % 16, i / 16);
    const Color8& k = image.texels[static_cast<size_t>(i)];
    for (int c = 0; c < 3; ++c) EXPECT_EQ(std::abs(a[c] - k[c]), std::abs(b[c] - k[c])) << i;
  }
  std::vector<float> grey;
  Rgba8Image grey_image{16, 4, {}};
  for (int i = 0; i < 64; ++i) {
    const u8 v = static_cast<u8>(i * 4 + 1);
    grey_image.texels.push_back({v, v, v, 255});
    for (int ch = 0; ch < 3; ++ch) grey.push_back(static_cast<float>(v / 255.0));
  }
  EXPECT_EQ(thickness_texture(16, 4, grey, TexFormat::I8).texture.data,
            encode_level(grey_image, TexFormat::I8, EncodeOptions{}).data);
}

}  // namespace
}  // namespace lt::gx
