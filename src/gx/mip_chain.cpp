// Mip levels by a 2x2 box filter (mip_chain.h).
#include "gx/mip_chain.h"

#include <algorithm>

#include "core/error.h"
#include "gx/texture_format.h"

namespace lt::gx {

Rgba8Image rgba8_of(const Image& image) {
  Rgba8Image out;
  out.width = image.width;
  out.height = image.height;
  out.texels.resize(image.pixel_count());
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const float* p = image.at(x, y);
      Color8& c = out.texels[static_cast<size_t>(y) * image.width + x];
      for (int ch = 0; ch < 4; ++ch) c[ch] = to_unorm8(p[ch]);
    }
  return out;
}

Rgba8Image box_filter_half(const Rgba8Image& level) {
  Rgba8Image out;
  out.width = std::max(1, level.width / 2);
  out.height = std::max(1, level.height / 2);
  out.texels.resize(static_cast<size_t>(out.width) * out.height);
  const int fx = level.width > 1 ? 2 : 1, fy = level.height > 1 ? 2 : 1;
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      int sum[4] = {};
      for (int dy = 0; dy < fy; ++dy)
        for (int dx = 0; dx < fx; ++dx) {
          const Color8& c = level.at(x * fx + dx, y * fy + dy);
          for (int ch = 0; ch < 4; ++ch) sum[ch] += c[ch];
        }
      const int n = fx * fy;
      Color8& c = out.texels[static_cast<size_t>(y) * out.width + x];
      for (int ch = 0; ch < 4; ++ch) c[ch] = static_cast<u8>((2 * sum[ch] + n) / (2 * n));
    }
  return out;
}

std::vector<Rgba8Image> mip_chain(const Rgba8Image& base, int levels) {
  LT_CHECK(levels >= 1 && levels <= full_mip_levels(base.width, base.height),
           "a mip chain has 1 .. full_mip_levels levels");
  std::vector<Rgba8Image> chain{base};
  while (static_cast<int>(chain.size()) < levels) chain.push_back(box_filter_half(chain.back()));
  return chain;
}

}  // namespace lt::gx
