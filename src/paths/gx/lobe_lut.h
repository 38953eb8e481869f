// The material's lobe as the texture GX_TEXMAP0 holds (gx.md §1): one row of W texels under
// texel-centre addressing (model/power_lut.h: texel i holds the lobe at t_i = i / (W - 1); the
// texgen folds in the remap s = t (W-1)/W + 0.5/W), each round(255 lobe(t_i)), in GX tile order.
// The generator writes it into the program as a u8 array; the path loads it where a program
// file loads none. One function, so the two can never differ.
#pragma once

#include <optional>

#include "gx/texture_format.h"
#include "gx/texture_unit.h"
#include "scene/scene.h"

namespace lt::gx {

// t^power as GX_TF_I8 (a material without translucency: the flat lobe of power 0). A lobe ramp
// (load/thickness_map.h) replaces t^power by the ramp at t_i (model::sample_ramp, linear between
// its texel centres, as the reference reads it): GX_TF_I8 for a grey ramp, GX_TF_RGBA8 for a
// coloured one, whose TEXC = (r, g, b) tints stage 0's lerp per channel.
// `grey_format` (the variant's :lut-format=) stores a grey LUT in I4, IA4 or IA8 instead of I8:
// the same 8-bit texels encoded by gx/texture_encoder.h with `nearest` rounding, the intensity
// also in alpha (as I8's TEXA is its intensity [DHW TextureDecoder_Common.cpp
// TexDecoder_DecodeTexel, case I8]), so the TEV reads the picture of I8 (IA8) or I4 (IA4). A
// colour ramp keeps GX_TF_RGBA8.
TextureObject lobe_lut(const Material& material, int width,
                       std::optional<TexFormat> grey_format = std::nullopt);

}  // namespace lt::gx
