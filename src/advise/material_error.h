// A material's error: the comparison `compare` makes, over the pixels that show one material
// (the G-buffer's material of each pixel) instead of every covered pixel, so that a scene with
// several materials gets one answer each.
#pragma once

#include <vector>

#include "metrics/compare.h"

namespace lt::advise {

// `covered` of the result is over the pixels where material_of_pixel == material (the reference
// of every other pixel is taken as uncovered); `image` is unchanged from compare_images.
Comparison compare_material(const Image& test, const Image& reference, TestEncoding encoding,
                            const std::vector<int>& material_of_pixel, int material);

// Pixels of the material whose test value is not finite (compare leaves them out of every
// figure and counts them over the whole image).
size_t non_finite_pixels(const Comparison& material_comparison);

}  // namespace lt::advise
