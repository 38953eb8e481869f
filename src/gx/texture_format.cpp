// GX texture formats: tiles and sizes (texture_format.h).
#include "gx/texture_format.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/error.h"

namespace lt::gx {

const TexFormatInfo& format_info(TexFormat format) {
  // [DHW TextureDecoder_Common.cpp TexDecoder_GetBlockWidthInTexels / Height /
  // GetTexelSizeInNibbles / TexDecoder_GetPaletteSize]
  static const TexFormatInfo kI4{"I4", 8, 8, 4, 32, 0}, kI8{"I8", 8, 4, 8, 32, 0},
      kIA4{"IA4", 8, 4, 8, 32, 0}, kIA8{"IA8", 4, 4, 16, 32, 0}, kRGB565{"RGB565", 4, 4, 16, 32, 0},
      kRGB5A3{"RGB5A3", 4, 4, 16, 32, 0}, kRGBA8{"RGBA8", 4, 4, 32, 64, 0},
      kCI4{"CI4", 8, 8, 4, 32, 16}, kCI8{"CI8", 8, 4, 8, 32, 256},
      kCI14X2{"CI14X2", 4, 4, 16, 32, 16384}, kCMPR{"CMPR", 8, 8, 4, 32, 0};
  switch (format) {
    case TexFormat::I4:
      return kI4;
    case TexFormat::I8:
      return kI8;
    case TexFormat::IA4:
      return kIA4;
    case TexFormat::IA8:
      return kIA8;
    case TexFormat::RGB565:
      return kRGB565;
    case TexFormat::RGB5A3:
      return kRGB5A3;
    case TexFormat::RGBA8:
      return kRGBA8;
    case TexFormat::CI4:
      return kCI4;
    case TexFormat::CI8:
      return kCI8;
    case TexFormat::CI14X2:
      return kCI14X2;
    case TexFormat::CMPR:
      return kCMPR;
  }
  LT_CHECK(false, "not a GX texture format");
  return kI8;
}

bool is_indexed(TexFormat format) {
  return format_info(format).tlut_entries > 0;
}

const char* tlut_format_name(TlutFormat format) {
  switch (format) {
    case TlutFormat::IA8:
      return "IA8";
    case TlutFormat::RGB565:
      return "RGB565";
    case TlutFormat::RGB5A3:
      return "RGB5A3";
  }
  LT_CHECK(false, "not a GX TLUT format");
  return "";
}

std::optional<TexFormat> tex_format_from_number(int number) {
  for (TexFormat f : kAllTexFormats)
    if (static_cast<int>(f) == number) return f;
  return std::nullopt;
}

namespace {

// Upper case without a GX_TF_ / GX_TL_ prefix: the spellings a user or a C program writes.
std::string format_key(std::string_view name, std::string_view prefix) {
  std::string key(name);
  for (char& c : key) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (key.rfind(prefix, 0) == 0) key.erase(0, prefix.size());
  return key;
}

}  // namespace

std::optional<TexFormat> tex_format_from_name(std::string_view name) {
  const std::string key = format_key(name, "GX_TF_");
  if (key == "CI14") return TexFormat::CI14X2;  // libogc's spelling of GX_TF_C14X2
  for (TexFormat f : kAllTexFormats)
    if (key == format_info(f).name) return f;
  return std::nullopt;
}

std::optional<TlutFormat> tlut_format_from_name(std::string_view name) {
  const std::string key = format_key(name, "GX_TL_");
  for (TlutFormat f : kAllTlutFormats)
    if (key == tlut_format_name(f)) return f;
  return std::nullopt;
}

std::size_t level_bytes(TexFormat format, int width, int height) {
  LT_CHECK(width >= 1 && height >= 1, "a texture level is at least 1x1");
  const TexFormatInfo& info = format_info(format);
  const std::size_t across =
      static_cast<std::size_t>((width + info.tile_width - 1) / info.tile_width);
  const std::size_t down =
      static_cast<std::size_t>((height + info.tile_height - 1) / info.tile_height);
  return across * down * static_cast<std::size_t>(info.tile_bytes);
}

std::size_t mip_chain_bytes(TexFormat format, int width, int height, int levels) {
  LT_CHECK(levels >= 1 && levels <= full_mip_levels(width, height),
           "a mip chain has 1 .. full_mip_levels levels");
  std::size_t bytes = 0;
  for (int level = 0; level < levels; ++level) {
    bytes += level_bytes(format, width, height);
    width = std::max(1, width >> 1);
    height = std::max(1, height >> 1);
  }
  return bytes;
}

int full_mip_levels(int width, int height) {
  int levels = 1;
  for (int size = std::max(width, height); size > 1; size >>= 1) ++levels;
  return levels;
}

}  // namespace lt::gx
