#include "paths/gx/lobe_lut.h"

#include <cmath>

#include "model/power_lut.h"

namespace lt::gx {

TextureObject lobe_lut(const Material& material, int width) {
  const double power = material.translucency ? material.translucency->power : 0.0;
  const model::PowerLut lut = model::PowerLut::build(width, model::LutFormat::U8, {power});
  std::vector<u8> row(static_cast<size_t>(width));
  for (int i = 0; i < width; ++i)
    row[static_cast<size_t>(i)] = static_cast<u8>(std::lround(lut.texel(0, i) * 255.0));
  TextureObject t;
  t.width = width;
  t.height = 1;
  t.format = kTexFormatI8;
  t.data = to_tiles(kTexFormatI8, width, 1, row);
  return t;
}

}  // namespace lt::gx
