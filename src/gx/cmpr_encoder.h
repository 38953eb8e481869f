// A CMPR encoder fitted to the console's palette: each 4x4 block's two RGB565 endpoints are
// chosen for the colours the texture unit actually makes of them, 5/8 c1 + 3/8 c2 and
// 3/8 c1 + 5/8 c2 truncated (texture_decoder.h cmpr_palette, [HWT gxtest/cmpr.cpp]), where a PC
// DXT1 encoder (the one gxtexconv uses, squish) fits thirds. Per block (docs/textures.md
// "CMPR"): candidates from the colours' principal axis, their bounding box, the best pair for a
// single colour in each mode, and least-squares endpoints for the console's weights; each is
// scored by decoding it exactly as the console does (the sum of squared RGB errors of the
// block's opaque texels, each texel taking its best palette colour) in both modes, then the best
// is improved by moving one endpoint field by one step at a time while the error falls.
// Texels with alpha below 128 are transparent: a block holding one uses the three-colour mode and
// gives it colour 3 (alpha 0).
#pragma once

#include <array>

#include "gx/texture_encoder.h"

namespace lt::gx {

// One block: 16 texels row-major, `valid` bit k set for texel k inside the image (padding
// texels of a partial block are ignored). Returns the 8 bytes as stored: c1 and c2 big-endian,
// then one byte a row, texel 0 in the top two bits.
std::array<u8, 8> encode_cmpr_block(const std::array<Color8, 16>& texels, unsigned valid);

// A whole level in GX tile order (8x8 tiles of four blocks).
EncodedLevel encode_cmpr(const Rgba8Image& image);

}  // namespace lt::gx
