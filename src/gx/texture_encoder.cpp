// Encoders to every GX texture format (texture_encoder.h).
#include "gx/texture_encoder.h"

#include <algorithm>
#include <cstdlib>

#include "core/error.h"
#include "gx/cmpr_encoder.h"
#include "gx/palette.h"
#include "gx/texture_decoder.h"

namespace lt::gx {

const char* rounding_name(Rounding rounding) {
  return rounding == Rounding::Nearest ? "nearest" : "truncate";
}

std::optional<Rounding> rounding_from_name(std::string_view name) {
  if (name == "nearest") return Rounding::Nearest;
  if (name == "truncate") return Rounding::Truncate;
  return std::nullopt;
}

namespace {

// The expansion the decoder applies to a field of `bits` bits (texture_decoder.h).
int expand(int field, int bits) {
  switch (bits) {
    case 3:
      return bits3_to_8(field);
    case 4:
      return bits4_to_8(field);
    case 5:
      return bits5_to_8(field);
    case 6:
      return bits6_to_8(field);
    default:
      return field;  // 8
  }
}

}  // namespace

int nearest_field(double v, int bits) {
  LT_CHECK((bits >= 3 && bits <= 6) || bits == 8, "a field of 3, 4, 5, 6 or 8 bits");
  const double target = std::clamp(v, 0.0, 255.0);
  // Expansion is monotonic, and the expansion of field f lies in [f << (8 - bits),
  // (f + 1) << (8 - bits)), so only the truncated field and its two neighbours can be nearest:
  // every field below them expands below the target, every field above them above the
  // truncated field's upper neighbour. Ties go to the lower field.
  const int truncated = static_cast<int>(target) >> (8 - bits);
  int best = std::max(truncated - 1, 0);
  for (int f = best + 1; f <= std::min(truncated + 1, (1 << bits) - 1); ++f)
    if (std::abs(expand(f, bits) - target) < std::abs(expand(best, bits) - target)) best = f;
  return best;
}

int quantise_component(int v, int bits, Rounding rounding) {
  LT_CHECK(v >= 0 && v <= 255, "an 8-bit component");
  if (rounding == Rounding::Truncate || bits == 8) return v >> (8 - bits);
  return nearest_field(v, bits);
}

u16 nearest_rgb565(double r, double g, double b) {
  return static_cast<u16>(nearest_field(std::clamp(r, 0.0, 1.0) * 255.0, 5) << 11 |
                          nearest_field(std::clamp(g, 0.0, 1.0) * 255.0, 6) << 5 |
                          nearest_field(std::clamp(b, 0.0, 1.0) * 255.0, 5));
}

int intensity_of(const Color8& c, Rounding rounding) {
  const int sum = c.r + c.g + c.b;
  return rounding == Rounding::Truncate ? sum / 3 : (sum * 2 + 3) / 6;  // (sum + 1.5) / 3
}

u16 encode_rgb565(const Color8& c, Rounding rounding) {
  return static_cast<u16>(quantise_component(c.r, 5, rounding) << 11 |
                          quantise_component(c.g, 6, rounding) << 5 |
                          quantise_component(c.b, 5, rounding));
}

u16 encode_rgb5a3(const Color8& c, Rounding rounding, bool opaque_image) {
  const bool opaque =
      rounding == Rounding::Truncate ? opaque_image : quantise_component(c.a, 3, rounding) == 7;
  if (opaque)
    return static_cast<u16>(0x8000 | quantise_component(c.r, 5, rounding) << 10 |
                            quantise_component(c.g, 5, rounding) << 5 |
                            quantise_component(c.b, 5, rounding));
  return static_cast<u16>(
      quantise_component(c.a, 3, rounding) << 12 | quantise_component(c.r, 4, rounding) << 8 |
      quantise_component(c.g, 4, rounding) << 4 | quantise_component(c.b, 4, rounding));
}

namespace {

void put16(std::vector<u8>& d, size_t at, u16 v) {
  d[at] = static_cast<u8>(v >> 8);
  d[at + 1] = static_cast<u8>(v);
}

// Stores `value` (a nibble, byte or 16-bit value of the format) for texel (x, y).
void store_texel(EncodedLevel& out, int x, int y, int value) {
  const TexelAddress at = texel_address(out.format, out.width, x, y);
  switch (format_info(out.format).bits_per_texel) {
    case 4:
      out.data[at.byte] |= static_cast<u8>(at.high_nibble ? value << 4 : value);
      break;
    case 8:
      out.data[at.byte] = static_cast<u8>(value);
      break;
    default:
      put16(out.data, at.byte, static_cast<u16>(value));
      break;
  }
}

}  // namespace

namespace {

// A level's texels as indices of `palette` starting at texel `first` of its index list.
EncodedLevel indexed_level(const Rgba8Image& image, TexFormat format, const Palette& palette,
                           size_t first, TlutFormat tlut_format) {
  EncodedLevel out;
  out.format = format;
  out.width = image.width;
  out.height = image.height;
  out.data.assign(level_bytes(format, image.width, image.height), 0);
  out.tlut_format = tlut_format;
  out.tlut.resize(palette.entries.size() * 2);
  for (size_t k = 0; k < palette.entries.size(); ++k) put16(out.tlut, 2 * k, palette.entries[k]);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      store_texel(out, x, y, palette.indices[first + static_cast<size_t>(y) * image.width + x]);
  return out;
}

}  // namespace

std::vector<EncodedLevel> encode_chain(const std::vector<Rgba8Image>& levels, TexFormat format,
                                       const EncodeOptions& options) {
  LT_CHECK(!levels.empty(), "a chain has a level");
  std::vector<EncodedLevel> out;
  if (!is_indexed(format)) {
    for (const Rgba8Image& level : levels) out.push_back(encode_level(level, format, options));
    return out;
  }
  Rgba8Image all{0, 1, {}};
  for (const Rgba8Image& level : levels)
    all.texels.insert(all.texels.end(), level.texels.begin(), level.texels.end());
  all.width = static_cast<int>(all.texels.size());
  const Palette palette =
      make_palette(all, format_info(format).tlut_entries, options.tlut_format, options.rounding);
  size_t first = 0;
  for (const Rgba8Image& level : levels) {
    out.push_back(indexed_level(level, format, palette, first, options.tlut_format));
    first += level.texels.size();
  }
  return out;
}

EncodedLevel encode_level(const Rgba8Image& image, TexFormat format, const EncodeOptions& options) {
  LT_CHECK(image.width >= 1 && image.width <= kMaxTextureSize && image.height >= 1 &&
               image.height <= kMaxTextureSize,
           "texture size must be 1..1024 per side");
  LT_CHECK(image.texels.size() == static_cast<size_t>(image.width) * image.height,
           "image texels must be width x height");
  if (format == TexFormat::CMPR) return encode_cmpr(image);
  const Rounding r = options.rounding;
  if (is_indexed(format))
    return indexed_level(
        image, format,
        make_palette(image, format_info(format).tlut_entries, options.tlut_format, r), 0,
        options.tlut_format);
  EncodedLevel out;
  out.format = format;
  out.width = image.width;
  out.height = image.height;
  out.data.assign(level_bytes(format, image.width, image.height), 0);
  const bool opaque_image = std::all_of(image.texels.begin(), image.texels.end(),
                                        [](const Color8& c) { return c.a == 255; });
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Color8& c = image.at(x, y);
      switch (format) {
        case TexFormat::I4:
          store_texel(out, x, y, quantise_component(intensity_of(c, r), 4, r));
          break;
        case TexFormat::I8:
          store_texel(out, x, y, intensity_of(c, r));
          break;
        case TexFormat::IA4:  // alpha the high nibble
          store_texel(
              out, x, y,
              quantise_component(c.a, 4, r) << 4 | quantise_component(intensity_of(c, r), 4, r));
          break;
        case TexFormat::IA8:  // alpha the first byte
          store_texel(out, x, y, c.a << 8 | intensity_of(c, r));
          break;
        case TexFormat::RGB565:
          store_texel(out, x, y, encode_rgb565(c, r));
          break;
        case TexFormat::RGB5A3:
          store_texel(out, x, y, encode_rgb5a3(c, r, opaque_image));
          break;
        case TexFormat::RGBA8: {  // (a, r) in the tile's first half, (g, b) 32 bytes on
          const TexelAddress at = texel_address(format, image.width, x, y);
          out.data[at.byte] = c.a;
          out.data[at.byte + 1] = c.r;
          out.data[at.byte + 32] = c.g;
          out.data[at.byte + 33] = c.b;
          break;
        }
        default:
          LT_CHECK(false, "format handled above");
          break;
      }
    }
  }
  return out;
}

}  // namespace lt::gx
