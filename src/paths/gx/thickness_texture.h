// A material's thickness map as the texture GX_TEXMAP1 holds (the gx path's extension of gx.md
// §1, where GX_TEXMAP0 holds the power LUT): the format the hardware offers for it, the texels
// quantised to that format, in GX tile order.
//
// Format: a grey map (r = g = b in every texel) is GX_TF_I8, 8 bits a texel, replicated into
// TEXC = (i, i, i) [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel, case I8]. A colour map
// is GX_TF_RGBA8 by default: 32 bits a texel, the 8 bits of an 8-bit map kept exactly, as the
// vertex colours it replaces keep theirs (GX_RGBA8 CLR0); alpha is unused (255). `rgb565` picks
// GX_TF_RGB565 instead: half the memory, 5/6/5 bits, each field expanded to 8 by bit
// replication, so a texel moves by up to 4 (r, b) or 2 (g) of 255. The variant's `:map=` picks
// the other formats (gx_variant.h map_texture_format): RGB5A3 and CMPR for a colour map, IA8,
// IA4 and I4 for a grey one; their texels are the map's 8-bit texels (below) encoded by
// gx/texture_encoder.h with `nearest` rounding (CMPR by gx/cmpr_encoder.h), alpha 255 (an IA
// format's alpha and RGB5A3's opaque RGB555: the alpha is unused).
//
// A float (EXR) map gets the same formats: GX has no float texture format (GX_TF_* are I4..RGBA8,
// the colour-indexed and CMPR ones), so each texel is quantised to the nearest 1/255 of `scale`
// (I8, RGBA8; at most 0.5/255 of it off) or to RGB565's nearest expansion: the least error each
// format allows (gx/texture_encoder.h's `nearest` rounding). A porter's converter may store less:
// devkitPro's gxtexconv truncates RGB565 fields (`r >> 3`, `g >> 2`, after an error diffusion),
// up to a whole step off where nearest is half a step (docs/textures.md "Encoding").
//
// Orientation: the map's texels are stored bottom row first (v = 0, OpenGL's convention, as
// model/texture_sampling.h keeps them), and GX's t = 0 is the first row in memory, so with the
// identity texgen (GX_IDENTITY) t = v addresses the same texel a GL path samples: the flip is in
// the data, done once here, not a texture matrix per vertex.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gx/texture_format.h"
#include "gx/texture_unit.h"
#include "scene/scene.h"

namespace lt::gx {

struct ThicknessTexture {
  TextureObject texture;  // tiled, GX_CLAMP both ways, linear
  // The thickness a texel of 255 stands for: 1 when every texel is at most 1 (an 8-bit map is
  // stored exactly), else the largest texel component (a float map over 1: the texels are
  // normalised to it and the generator moves it into the light's magnitude).
  double scale = 1;
  std::string format_name = "GX_TF_I8";  // the GX_TF_* name for the program
};

// `rgb` holds width x height texels of three floats, row 0 the image's bottom row; every value
// is finite and >= 0 (the scene checked it). Width and height are 1..1024 (the caller refuses
// larger maps with the scene key). `format` is any format but CI14X2 (the caller picks it by
// `grey`: gx_variant.h map_texture_format); a colour map in a grey format stores
// the encoder's intensity (the mean of r, g and b). A colour-indexed format gets its palette
// (gx/palette.h, median cut of the 8-bit texels) in `tlut_format`, in texture.tlut.
ThicknessTexture thickness_texture(int width, int height, const std::vector<float>& rgb,
                                   TexFormat format, TlutFormat tlut_format = TlutFormat::RGB565);

// `levels` levels of `tex` (made by thickness_texture from the same texels, format and TLUT
// format) instead of one: level 0 and each smaller one (gx/mip_chain.h's box filter of the map's
// 8-bit texels), encoded by gx/texture_encoder.h with `nearest` rounding and stored one after
// another (TextureObject::levels). A colour-indexed texture's palette is made again from every
// level's texels (encode_chain: one TLUT for the chain), so its level 0 may change; the other
// formats keep thickness_texture's level 0. Sides powers of two (the caller refuses others).
void add_mip_levels(ThicknessTexture& tex, const std::vector<float>& rgb, int levels,
                    TlutFormat tlut_format = TlutFormat::RGB565);

// A material's thickness map as the scene loaded it (load/thickness_map.h): float rgb texels,
// row 0 the image's bottom row; empty when the material's thickness is not a map.
struct MapTexels {
  int width = 0, height = 0;
  const std::vector<float>* rgb = nullptr;
  bool grey = false;
};
std::optional<MapTexels> thickness_map_texels(const Material& material);

}  // namespace lt::gx
