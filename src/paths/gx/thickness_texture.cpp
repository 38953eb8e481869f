#include "paths/gx/thickness_texture.h"

#include <algorithm>

#include "core/error.h"
#include "gx/mip_chain.h"
#include "gx/texture_encoder.h"
#include "image/image.h"

namespace lt::gx {

namespace {

// The 8-bit texel of a thickness in [0, scale], rounded to nearest: an 8-bit map's k / 255 comes
// back as k exactly.
u8 to_byte(double v, double scale) {
  return to_unorm8(v / scale);
}

// The map as 8-bit RGBA (alpha 255) for the tree's encoders, memory row 0 its bottom row.
Rgba8Image map_image(int width, int height, const std::vector<float>& rgb, double scale) {
  Rgba8Image image;
  image.width = width;
  image.height = height;
  image.texels.reserve(rgb.size() / 3);
  for (size_t i = 0; i < rgb.size(); i += 3)
    image.texels.push_back(
        {to_byte(rgb[i], scale), to_byte(rgb[i + 1], scale), to_byte(rgb[i + 2], scale), 255});
  return image;
}

}  // namespace

ThicknessTexture thickness_texture(int width, int height, const std::vector<float>& rgb,
                                   TexFormat format, TlutFormat tlut_format) {
  LT_CHECK(width >= 1 && width <= kMaxTextureSize && height >= 1 && height <= kMaxTextureSize,
           "the caller refuses thickness maps over 1024 texels a side");
  const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
  LT_CHECK(rgb.size() == n * 3, "thickness texels must be width x height x 3");
  ThicknessTexture out;
  const float top = rgb.empty() ? 0.0f : *std::max_element(rgb.begin(), rgb.end());
  out.scale = top > 1.0f ? static_cast<double>(top) : 1.0;
  LT_CHECK(format != TexFormat::CI14X2, "a map is never CI14X2 (gx_variant.h)");
  out.format_name = std::string("GX_TF_") + format_info(format).name;
  TextureObject& tex = out.texture;
  tex.width = width;
  tex.height = height;
  tex.format = static_cast<u8>(format);
  tex.wrap_s = tex.wrap_t = 0;  // GX_CLAMP, as the reference's CLAMP_TO_EDGE
  tex.linear = true;
  const bool grey = format == TexFormat::I8, rgb565 = format == TexFormat::RGB565;
  if (!grey && !rgb565 && format != TexFormat::RGBA8) {
    // Every other format through the tree's encoders; I8, RGB565 and RGBA8 keep the loop below,
    // whose bytes the frames made before :map=FMT hold (RGB565 from the float texel itself).
    EncodedLevel level = encode_level(map_image(width, height, rgb, out.scale), format,
                                      EncodeOptions{Rounding::Nearest, tlut_format});
    tex.data = std::move(level.data);
    if (is_indexed(format)) {
      tex.tlut = std::move(level.tlut);
      tex.tlut_format = static_cast<u8>(tlut_format);
    }
    return out;
  }
  std::vector<u8> row_major;
  row_major.reserve(n * (grey ? 1 : rgb565 ? 2 : 4));
  // Texel i of `rgb` is memory row y = i / W: bottom row first, so t = v (the header).
  for (size_t i = 0; i < n; ++i) {
    const float* t = &rgb[i * 3];
    if (grey) {
      row_major.push_back(to_byte(t[0], out.scale));
    } else if (rgb565) {
      const u16 v = nearest_rgb565(t[0] / out.scale, t[1] / out.scale, t[2] / out.scale);
      row_major.push_back(static_cast<u8>(v >> 8));  // stored big-endian (texture_unit.h)
      row_major.push_back(static_cast<u8>(v & 0xff));
    } else {
      for (int c = 0; c < 3; ++c) row_major.push_back(to_byte(t[c], out.scale));
      row_major.push_back(255);
    }
  }
  tex.data = to_tiles(tex.format, width, height, row_major);
  return out;
}

void add_mip_levels(ThicknessTexture& tex, const std::vector<float>& rgb, int levels,
                    TlutFormat tlut_format) {
  TextureObject& o = tex.texture;
  LT_CHECK(o.levels == 1 && levels >= 1 && levels <= full_mip_levels(o.width, o.height),
           "a map's levels are 1 .. full_mip_levels");
  const auto format = static_cast<TexFormat>(o.format);
  const std::vector<EncodedLevel> chain =
      encode_chain(mip_chain(map_image(o.width, o.height, rgb, tex.scale), levels), format,
                   EncodeOptions{Rounding::Nearest, tlut_format});
  if (is_indexed(format)) {
    o.data.clear();
    o.tlut = chain.front().tlut;
  } else {
    o.data.resize(level_bytes(format, o.width, o.height));  // thickness_texture's level 0
  }
  for (size_t k = is_indexed(format) ? 0 : 1; k < chain.size(); ++k)
    o.data.insert(o.data.end(), chain[k].data.begin(), chain[k].data.end());
  o.levels = levels;
}

std::optional<MapTexels> thickness_map_texels(const Material& material) {
  if (!material.translucency || material.translucency->thickness_source != ThicknessSource::Texture)
    return std::nullopt;
  const TextureMap& map = *material.translucency->thickness_map;
  return MapTexels{map.texture.width, map.texture.height, &map.texture.texels, map.grey};
}

}  // namespace lt::gx
