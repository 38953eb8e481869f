// The GX texture encoders (src/gx/texture_encoder.h, palette.h, cmpr_encoder.h, mip_chain.h):
// each rounding against an exhaustive search or gxtexconv's shift, every format decoded back
// (texture_decoder.h) within the bound its field widths allow, palettes that reproduce images of
// few colours exactly, CMPR blocks the console's palette can hold exactly found exactly.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "gx/cmpr_encoder.h"
#include "gx/mip_chain.h"
#include "gx/texture_decoder.h"
#include "gx/texture_encoder.h"

namespace lt::gx {
namespace {

int expansion(int field, int bits) {
  switch (bits) {
    case 3: return bits3_to_8(field);
    case 4: return bits4_to_8(field);
    case 5: return bits5_to_8(field);
    case 6: return bits6_to_8(field);
    default: return field;
  }
}

TEST(GxTextureEncoder, NearestRoundingIsTheNearestExpansionByExhaustiveSearch) {
  for (int bits : {3, 4, 5, 6, 8})
    for (int v = 0; v < 256; ++v) {
      int best = 0;  // the lowest field of least distance
      for (int f = 1; f < (1 << bits); ++f)
        if (std::abs(expansion(f, bits) - v) < std::abs(expansion(best, bits) - v)) best = f;
      EXPECT_EQ(quantise_component(v, bits, Rounding::Nearest), best) << bits << " bits, " << v;
    }
}

TEST(GxTextureEncoder, TruncateIsGxtexconvsShift) {
  // gxtexconv: `r >> 3`, `g >> 2` (RGB565), `>> 4` (RGB5A3's 4-bit fields, I4), `a >> 5`.
  EXPECT_EQ(quantise_component(255, 5, Rounding::Truncate), 31);
  EXPECT_EQ(quantise_component(7, 5, Rounding::Truncate), 0);
  EXPECT_EQ(quantise_component(8, 5, Rounding::Truncate), 1);
  EXPECT_EQ(quantise_component(3, 6, Rounding::Truncate), 0);
  EXPECT_EQ(quantise_component(250, 4, Rounding::Truncate), 15);
  EXPECT_EQ(quantise_component(223, 3, Rounding::Truncate), 6);
  // Where the two differ: 7 is nearest to 8 (field 1) but truncates to 0.
  EXPECT_EQ(quantise_component(7, 5, Rounding::Nearest), 1);
  // Intensity: (10 + 10 + 11) / 3 = 10.33 -> 10 both ways; (10 + 11 + 11) / 3 = 10.67 -> 11, 10.
  EXPECT_EQ(intensity_of({10, 10, 11, 255}, Rounding::Nearest), 10);
  EXPECT_EQ(intensity_of({10, 11, 11, 255}, Rounding::Nearest), 11);
  EXPECT_EQ(intensity_of({10, 11, 11, 255}, Rounding::Truncate), 10);
}

Rgba8Image random_image(int w, int h, unsigned seed, bool grey, bool opaque) {
  std::mt19937 rng(seed);
  Rgba8Image image{w, h, {}};
  for (int k = 0; k < w * h; ++k) {
    Color8 c{static_cast<u8>(rng()), static_cast<u8>(rng()), static_cast<u8>(rng()),
             opaque ? u8{255} : static_cast<u8>(rng())};
    if (grey) c.g = c.b = c.r;
    image.texels.push_back(c);
  }
  return image;
}

// The largest component error after encoding and decoding back.
int worst_error(const Rgba8Image& image, TexFormat format, const EncodeOptions& options,
                bool with_alpha) {
  const EncodedLevel level = encode_level(image, format, options);
  EXPECT_EQ(level.data.size(), level_bytes(format, image.width, image.height));
  const TlutView tlut{level.tlut_format, level.tlut};
  const std::vector<Color8> back =
      decode_texture({format, image.width, image.height, level.data}, &tlut);
  int worst = 0;
  for (size_t k = 0; k < back.size(); ++k)
    for (int c = 0; c < (with_alpha ? 4 : 3); ++c)
      worst = std::max(worst, std::abs(back[k][c] - image.texels[k][c]));
  return worst;
}

TEST(GxTextureEncoder, EveryDirectFormatDecodesBackWithinItsFieldsStep) {
  // Nearest: half the largest gap between expansions (3 bits 37, 4 bits 17, 5 bits 9, 6 bits 5),
  // rounded down; truncate: up to one whole step. Grey images for the intensity formats, and
  // their mean of r, g, b is then r exactly.
  const Rgba8Image grey = random_image(13, 11, 1, true, false);
  const Rgba8Image colour = random_image(13, 11, 2, false, false);
  const Rgba8Image opaque = random_image(13, 11, 3, false, true);
  const EncodeOptions nearest{Rounding::Nearest}, truncate{Rounding::Truncate};
  EXPECT_EQ(worst_error(grey, TexFormat::I8, nearest, false), 0);
  EXPECT_EQ(worst_error(grey, TexFormat::IA8, nearest, true), 0);
  EXPECT_EQ(worst_error(colour, TexFormat::RGBA8, nearest, true), 0);
  EXPECT_LE(worst_error(grey, TexFormat::I4, nearest, false), 8);
  EXPECT_LE(worst_error(grey, TexFormat::IA4, nearest, true), 8);
  EXPECT_LE(worst_error(opaque, TexFormat::RGB565, nearest, false), 4);
  EXPECT_LE(worst_error(opaque, TexFormat::RGB5A3, nearest, true), 4);
  EXPECT_LE(worst_error(colour, TexFormat::RGB5A3, nearest, true), 18);
  EXPECT_LE(worst_error(grey, TexFormat::I4, truncate, false), 17);
  EXPECT_LE(worst_error(opaque, TexFormat::RGB565, truncate, false), 8);
  EXPECT_LE(worst_error(colour, TexFormat::RGB5A3, truncate, true), 37);
  // Truncation is worse on random data than nearest, never better per texel.
  EXPECT_GT(worst_error(opaque, TexFormat::RGB565, truncate, false),
            worst_error(opaque, TexFormat::RGB565, nearest, false));
}

TEST(GxTextureEncoder, RepresentableColoursRoundTripExactlyUnderBothRoundings) {
  // Texels made of expansions of fields: nearest and truncate both store the field itself.
  std::mt19937 rng(5);
  Rgba8Image image{9, 6, {}};
  for (int k = 0; k < 54; ++k)
    image.texels.push_back({bits5_to_8(static_cast<int>(rng() % 32)),
                            bits6_to_8(static_cast<int>(rng() % 64)),
                            bits5_to_8(static_cast<int>(rng() % 32)), 255});
  for (Rounding r : {Rounding::Nearest, Rounding::Truncate})
    EXPECT_EQ(worst_error(image, TexFormat::RGB565, {r}, true), 0) << rounding_name(r);
}

TEST(GxTextureEncoder, PalettesOfFewColoursAreExact) {
  // 12 representable RGB5A3 colours (opaque 555 and translucent 4443) in a 20x10 image: median
  // cut separates every distinct colour, so CI4 and CI8 reproduce it exactly; CI14X2 too.
  std::vector<Color8> colours;
  for (int k = 0; k < 6; ++k) {
    colours.push_back({bits5_to_8(k * 5), bits5_to_8(31 - k), bits5_to_8(k * 3), 255});
    colours.push_back({bits4_to_8(k), bits4_to_8(15 - k), bits4_to_8(k * 2), bits3_to_8(k)});
  }
  Rgba8Image image{20, 10, {}};
  for (int k = 0; k < 200; ++k) image.texels.push_back(colours[static_cast<size_t>((k * 7) % 12)]);
  for (TexFormat f : {TexFormat::CI4, TexFormat::CI8, TexFormat::CI14X2}) {
    const EncodeOptions options{Rounding::Nearest, TlutFormat::RGB5A3};
    EXPECT_EQ(worst_error(image, f, options, true), 0) << format_info(f).name;
    EXPECT_EQ(encode_level(image, f, options).tlut.size(), 12u * 2);
  }
  // More colours than CI4 holds: 16 entries at most, every index below 16.
  const Rgba8Image many = random_image(16, 16, 9, false, true);
  const EncodedLevel ci4 = encode_level(many, TexFormat::CI4, {Rounding::Nearest, TlutFormat::RGB565});
  EXPECT_EQ(ci4.tlut.size(), 16u * 2);
  EXPECT_LT(largest_index({TexFormat::CI4, 16, 16, ci4.data}), 16);
}

std::array<Color8, 16> block_of(const std::array<Color8, 4>& palette, const int numbers[16]) {
  std::array<Color8, 16> texels{};
  for (int k = 0; k < 16; ++k) texels[static_cast<size_t>(k)] = palette[static_cast<size_t>(numbers[k])];
  return texels;
}

std::array<Color8, 16> decode_block(const std::array<u8, 8>& bytes) {
  std::vector<u8> tile(32, 0);
  std::copy(bytes.begin(), bytes.end(), tile.begin());
  std::array<Color8, 16> out{};
  for (int k = 0; k < 16; ++k)
    out[static_cast<size_t>(k)] = decode_texel({TexFormat::CMPR, 4, 4, tile}, k & 3, k >> 2);
  return out;
}

TEST(GxCmprEncoder, BlocksOfTheConsolesPaletteAreFoundExactly) {
  // Texels drawn from the console's four colours of random endpoints (c1 > c2): the 3/8-5/8 mix
  // a DXT1 encoder would miss by its thirds. The encoder must find a block decoding to them.
  std::mt19937 rng(3897);
  for (int trial = 0; trial < 40; ++trial) {
    u16 c1 = static_cast<u16>(rng()), c2 = static_cast<u16>(rng());
    if (c1 == c2) continue;
    if (c1 < c2) std::swap(c1, c2);
    int numbers[16];
    for (int& n : numbers) n = static_cast<int>(rng() % 4);
    const std::array<Color8, 16> texels = block_of(cmpr_palette(c1, c2), numbers);
    EXPECT_EQ(decode_block(encode_cmpr_block(texels, 0xffff)), texels) << trial;
  }
}

TEST(GxCmprEncoder, OneColourBlocksUseTheBestBlendOfTwoEndpoints) {
  // (100, 100, 100) is no RGB565 colour (5 bits: 99 or 107; 6 bits: 97 or 101), but a 5/8-3/8
  // mix or an average of two can be: the encoder's block is at most as far as the nearest
  // single endpoint, whose error is (1, 1, 1) per component... (|99-100|, |101-100|, |99-100|).
  std::array<Color8, 16> texels;
  texels.fill({100, 100, 100, 255});
  const std::array<Color8, 16> back = decode_block(encode_cmpr_block(texels, 0xffff));
  for (const Color8& c : back) {
    EXPECT_LE(std::abs(c.r - 100), 1);
    EXPECT_LE(std::abs(c.g - 100), 1);
    EXPECT_LE(std::abs(c.b - 100), 1);
  }
  // An exact one: 5/8 * 255 + 3/8 * 0 = 159.375 -> 159 (red); the encoder finds error 0.
  texels.fill({159, 0, 0, 255});
  for (const Color8& c : decode_block(encode_cmpr_block(texels, 0xffff)))
    EXPECT_EQ(c, (Color8{159, 0, 0, 255}));
}

TEST(GxCmprEncoder, TransparentTexelsGetColourThreeOfTheThreeColourMode) {
  std::array<Color8, 16> texels;
  texels.fill({200, 40, 40, 255});
  texels[5] = {0, 0, 0, 0};
  texels[10] = {90, 90, 90, 100};  // alpha below 128: transparent
  const std::array<u8, 8> bytes = encode_cmpr_block(texels, 0xffff);
  const u16 c1 = static_cast<u16>(bytes[0] << 8 | bytes[1]), c2 = static_cast<u16>(bytes[2] << 8 | bytes[3]);
  EXPECT_LE(c1, c2);
  const std::array<Color8, 16> back = decode_block(bytes);
  EXPECT_EQ(back[5].a, 0);
  EXPECT_EQ(back[10].a, 0);
  EXPECT_EQ(back[0].a, 255);
  EXPECT_LE(std::abs(back[0].r - 200), 4);
}

TEST(GxCmprEncoder, PartialBlocksIgnoreTheirPadding) {
  // A 5x3 image: its second block holds one real column; the padding must not pull the colour.
  Rgba8Image image{5, 3, {}};
  for (int k = 0; k < 15; ++k)
    image.texels.push_back(k % 5 == 4 ? Color8{bits5_to_8(3), bits6_to_8(60), bits5_to_8(9), 255}
                                      : Color8{10, 20, 30, 255});
  const EncodedLevel level = encode_cmpr(image);
  const std::vector<Color8> back = decode_texture({TexFormat::CMPR, 5, 3, level.data});
  for (int y = 0; y < 3; ++y) EXPECT_EQ(back[static_cast<size_t>(y * 5 + 4)], image.texels[static_cast<size_t>(y * 5 + 4)]);
}

TEST(GxMipChain, BoxFilterAveragesTwoByTwoAndRoundsHalfUp) {
  // 3x2 -> 1x1: texels (0..1, 0..1); the odd third column is dropped. 1x4 -> 1x2: pairs along y.
  Rgba8Image a{3, 2, {{0, 0, 0, 0}, {1, 10, 255, 255}, {99, 99, 99, 99},
                      {0, 0, 0, 0}, {2, 10, 255, 255}, {99, 99, 99, 99}}};
  EXPECT_EQ(box_filter_half(a).texels, (std::vector<Color8>{{1, 5, 128, 128}}));  // 3/4 -> 1
  Rgba8Image b{1, 4, {{0, 0, 0, 0}, {3, 3, 3, 3}, {10, 10, 10, 10}, {11, 11, 11, 11}}};
  EXPECT_EQ(box_filter_half(b).texels, (std::vector<Color8>{{2, 2, 2, 2}, {11, 11, 11, 11}}));
  const std::vector<Rgba8Image> chain = mip_chain(random_image(8, 2, 4, false, false), 4);
  ASSERT_EQ(chain.size(), 4u);
  EXPECT_EQ(chain[1].width, 4);
  EXPECT_EQ(chain[3].width, 1);
  EXPECT_EQ(chain[3].height, 1);
}

}  // namespace
}  // namespace lt::gx
