#include "advise/material_error.h"

#include <cmath>

#include "core/error.h"

namespace lt::advise {

Comparison compare_material(const Image& test, const Image& reference, TestEncoding encoding,
                            const std::vector<int>& material_of_pixel, int material) {
  LT_CHECK(material_of_pixel.size() == static_cast<size_t>(reference.width) * reference.height,
           "one material index a pixel");
  Image masked = reference;
  for (size_t i = 0; i < material_of_pixel.size(); ++i) {
    if (material_of_pixel[i] != material) masked.rgba[i * 4 + 3] = 0;
  }
  // Both coverages: the covered region is this material's pixels the test covers too (the
  // mismatch counts, over other materials' pixels, mean nothing here and are not judged).
  return compare_images(test, masked, encoding, TestEncoding::kFloat, Coverage::kBoth);
}

size_t non_finite_pixels(const Comparison& c) {
  size_t n = 0;
  for (size_t i = 0; i < c.pixel_error_lsb.size(); ++i) {
    if (c.covered_mask[i] && std::isnan(c.pixel_error_lsb[i])) ++n;
  }
  return n;
}

}  // namespace lt::advise
