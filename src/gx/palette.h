// A palette for a colour-indexed texture (CI4, CI8, CI14X2) made from an image by median cut
// (Heckbert 1982, "Color image quantization for frame buffer display"): the texels' RGBA
// bounding box is split at the median of its longest side, the box with the longest side first,
// until there are as many boxes as entries or no box holds two different colours. Each entry is
// its box's mean colour stored in the TLUT format with the encoder's rounding
// (texture_encoder.h). Each texel then takes the entry whose decoded colour is nearest (squared
// RGBA distance, lowest index on ties) for CI4 and CI8; CI14X2's 16,384 entries are too many to
// search per texel, so a texel there takes its own box's entry (docs/textures.md).
#pragma once

#include <vector>

#include "gx/texture_encoder.h"

namespace lt::gx {

struct Palette {
  std::vector<u16> entries;  // TLUT values (big-endian when stored), at most max_entries
  std::vector<int> indices;  // one per texel, row-major
};

Palette make_palette(const Rgba8Image& image, int max_entries, TlutFormat format,
                     Rounding rounding);

// A TLUT entry of `format` for colour c (IA8: alpha first byte, intensity second).
u16 encode_tlut_entry(const Color8& c, TlutFormat format, Rounding rounding);

}  // namespace lt::gx
