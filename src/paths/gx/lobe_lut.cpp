#include "paths/gx/lobe_lut.h"

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

}  // namespace

TextureObject lobe_lut(const Material& material, int width) {
  if (material.translucency && material.translucency->ramp)
    return ramp_lut(*material.translucency->ramp, width);
  const double power = material.translucency ? material.translucency->power : 0.0;
  const model::PowerLut lut = model::PowerLut::build(width, model::LutFormat::U8, {power});
  std::vector<u8> row(static_cast<size_t>(width));
  for (int i = 0; i < width; ++i) row[static_cast<size_t>(i)] = to_unorm8(lut.texel(0, i));
  return one_row(kTexFormatI8, width, row);
}

}  // namespace lt::gx
