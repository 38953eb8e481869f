// The pixel-walking helpers of test_util.h, compiled optimised (lt_test_support in
// cmake/test_binaries.cmake) while the test files themselves are compiled at -O0.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "test_util.h"

namespace lt::test {

size_t non_finite(const Image& img) {
  size_t n = 0;
  for (float v : img.rgba) n += !std::isfinite(v);
  return n;
}

size_t covered_pixels(const Image& img) {
  size_t n = 0;
  for (size_t i = 0; i < img.pixel_count(); ++i) n += img.rgba[i * 4 + 3] > 0.5f;
  return n;
}

PictureDifference picture_difference(const Image& a, const Image& b) {
  PictureDifference d;
  if (a.width != b.width || a.height != b.height) {
    ADD_FAILURE() << "pictures of " << a.width << "x" << a.height << " and " << b.width << "x"
                  << b.height;
    d.differ = a.pixel_count();
    return d;
  }
  for (size_t i = 0; i < a.pixel_count(); ++i) {
    int m = 0;
    for (size_t ch = 0; ch < 3; ++ch)
      m = std::max(m, std::abs(static_cast<int>(std::lround(a.rgba[i * 4 + ch] * 255.0f)) -
                               static_cast<int>(std::lround(b.rgba[i * 4 + ch] * 255.0f))));
    if (m == 0) continue;
    if (d.differ++ == 0) {
      d.first_x = static_cast<int>(i % static_cast<size_t>(a.width));
      d.first_y = static_cast<int>(i / static_cast<size_t>(a.width));
    }
    d.max = std::max(d.max, m);
  }
  return d;
}

}  // namespace lt::test
