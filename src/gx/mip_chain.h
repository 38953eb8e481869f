// A texture's source and its mip levels: the image as 8-bit RGBA (to_unorm8 of each component,
// image/image.h: the one rounding of every 8-bit value ltrender makes) and each smaller level
// made from the one before by a 2x2 box filter (docs/textures.md "Mipmaps"):
//   level n+1 is max(1, w/2) x max(1, h/2); its texel (x, y) is the mean of the texels
//   (2x .. 2x+1, 2y .. 2y+1) of level n that exist (one or two of them along a side of length
//   1), rounded to nearest (half up), each component on its own, alpha included.
// An odd side drops its last row or column, as halving a size register does (GX's levels are
// each half the size before, rounded down [OGC gx.c GX_GetTexBufferSize L3117-3136]).
#pragma once

#include <vector>

#include "gx/texture_encoder.h"
#include "image/image.h"

namespace lt::gx {

// row 0 of `image` (its top row) becomes t = 0, the first row in texture memory.
Rgba8Image rgba8_of(const Image& image);
Rgba8Image box_filter_half(const Rgba8Image& level);
// Levels 0 .. levels-1 (levels from 1 to full_mip_levels(width, height)).
std::vector<Rgba8Image> mip_chain(const Rgba8Image& base, int levels);

}  // namespace lt::gx
