#include "paths/gx/lobe_lut.h"

#include "gx/texture_encoder.h"
#include "image/image.h"
#include "model/power_lut.h"
#include "model/texture_sampling.h"

namespace lt::gx {

namespace {

// One row of texels (row-major in `format`'s layout) as the tiled texture.
TextureObject one_row(u8 format, int width, const std::vector<u8>& row) {
  TextureObject t;
  t.width = width;
  t.height = 1;
  t.format = format;
  t.data = to_tiles(format, width, 1, row);
  return t;
}

TextureObject ramp_lut(const TextureMap& ramp, int width) {
  const u8 format = ramp.grey ? kTexFormatI8 : kTexFormatRGBA8;
  std::vector<u8> row;
  for (int i = 0; i < width; ++i) {
    const glm::dvec3 v = model::sample_ramp(ramp.texture, static_cast<double>(i) / (width - 1));
    if (ramp.grey) {
      row.push_back(to_unorm8(v.r));
    } else {
      for (int c = 0; c < 3; ++c) row.push_back(to_unorm8(v[c]));
      row.push_back(255);
    }
  }
  return one_row(format, width, row);
}

// The grey row in another grey format: each texel (v, v, v, v) encoded to nearest.
TextureObject grey_row(TexFormat format, int width, const std::vector<u8>& row) {
  Rgba8Image image;
  image.width = width;
  image.height = 1;
  for (u8 v : row) image.texels.push_back({v, v, v, v});
  TextureObject t;
  t.width = width;
  t.height = 1;
  t.format = static_cast<u8>(format);
  t.data = encode_level(image, format, EncodeOptions{}).data;
  return t;
}

}  // namespace

TextureObject lobe_lut(const Material& material, int width, std::optional<TexFormat> grey_format) {
  const bool in_i8 = !grey_format || *grey_format == TexFormat::I8;
  if (material.translucency && material.translucency->ramp) {
    const TextureMap& ramp = *material.translucency->ramp;
    if (in_i8 || !ramp.grey) return ramp_lut(ramp, width);
    const TextureObject i8 = ramp_lut(ramp, width);
    std::vector<u8> row(static_cast<size_t>(width));
    for (int i = 0; i < width; ++i) row[static_cast<size_t>(i)] = texel_at(i8, i, 0).r;
    return grey_row(*grey_format, width, row);
  }
  const double power = material.translucency ? material.translucency->power : 0.0;
  const model::PowerLut lut = model::PowerLut::build(width, model::LutFormat::U8, {power});
  std::vector<u8> row(static_cast<size_t>(width));
  for (int i = 0; i < width; ++i) row[static_cast<size_t>(i)] = to_unorm8(lut.texel(0, i));
  return in_i8 ? one_row(kTexFormatI8, width, row) : grey_row(*grey_format, width, row);
}

}  // namespace lt::gx
