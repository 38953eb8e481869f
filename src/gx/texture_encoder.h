// Encoders from 8-bit RGBA images to every GX texture format (texture_format.h), the bytes in
// GX tile order as the texture unit reads them (texture_decoder.h). Each rounding is named
// (docs/textures.md "Encoding"):
//  - nearest:  each field holds the value whose bit-replicated expansion is nearest to the
//              8-bit component (ties to the lower field): the least error the format allows.
//  - truncate: each 8-bit component shifted right to the field's width, `v >> (8 - bits)`, as
//              devkitPro's gxtexconv stores its fields [gamecube-tools gxtool/tfbinary.cpp
//              WriteTexture_I4 .. WriteTexture_RGB5A3, WritePaletteBlock]; intensity is the
//              truncated mean (r + g + b) / 3 as gxtexconv takes it. gxtexconv also diffuses
//              the error of RGB565 textures and of palettes over neighbours first
//              (gxtool/image.cpp CImage::DiffuseError); this encoder does not.
// CMPR has its own encoder (cmpr_encoder.h), fitted to the console's 3/8-5/8 palette.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "gx/gx_types.h"
#include "gx/texture_format.h"

namespace lt::gx {

enum class Rounding { Nearest, Truncate };
const char* rounding_name(Rounding rounding);  // "nearest", "truncate"
std::optional<Rounding> rounding_from_name(std::string_view name);

// An image as a texture converter reads it: 8-bit RGBA, row-major, row 0 the first row in
// texture memory (t = 0).
struct Rgba8Image {
  int width = 0, height = 0;
  std::vector<Color8> texels;
  const Color8& at(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }
};

struct EncodeOptions {
  Rounding rounding = Rounding::Nearest;
  TlutFormat tlut_format = TlutFormat::RGB565;  // the palette's format (CI4, CI8, CI14X2)
};

// One encoded level, and for colour-indexed formats its palette (TLUT bytes in memory order,
// format_info(format).tlut_entries entries at most, as many as the palette generation made).
struct EncodedLevel {
  TexFormat format = TexFormat::I8;
  int width = 0, height = 0;
  std::vector<u8> data;  // level_bytes(format, width, height); padding texels are zero
  TlutFormat tlut_format = TlutFormat::RGB565;
  std::vector<u8> tlut;  // empty unless is_indexed(format)
};

// The field (0 .. 2^bits - 1) that stores the 8-bit component v under `rounding`.
int quantise_component(int v, int bits, Rounding rounding);
// The field (0 .. 2^bits - 1) whose expansion (texture_decoder.h) is nearest to v, a value in
// 0..255 that need not be whole (clamped); ties to the lower field.
int nearest_field(double v, int bits);
// The RGB565 value whose expansion is nearest to the linear colour (r, g, b) in [0, 1] per
// component (clamped; ties to the lower field): the best a texture converter can store.
u16 nearest_rgb565(double r, double g, double b);
// The intensity a grey format stores for a colour: the mean of r, g and b (rounded to nearest,
// or truncated as gxtexconv does).
int intensity_of(const Color8& c, Rounding rounding);

// Packed 16-bit values (big-endian order when stored).
u16 encode_rgb565(const Color8& c, Rounding rounding);
// RGB5A3: nearest picks per texel: opaque RGB555 when alpha's nearest 3-bit field is 7, else
// a3 r4 g4 b4. Truncate uses gxtexconv's rule for the whole image (`opaque`: no texel with alpha
// below 255 gives RGB555 everywhere, else a3 r4 g4 b4 everywhere).
u16 encode_rgb5a3(const Color8& c, Rounding rounding, bool opaque_image);

// Every format; CMPR through cmpr_encoder.h (its rounding is its own), the colour-indexed ones
// through palette.h. LT_CHECK on a size outside 1..1024.
EncodedLevel encode_level(const Rgba8Image& image, TexFormat format, const EncodeOptions& options);
// A mip chain's levels (mip_chain.h) encoded one after another. A colour-indexed chain shares
// one palette (a texture has one TLUT): made from the texels of every level together.
std::vector<EncodedLevel> encode_chain(const std::vector<Rgba8Image>& levels, TexFormat format,
                                       const EncodeOptions& options);

}  // namespace lt::gx
