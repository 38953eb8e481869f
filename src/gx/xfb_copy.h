// The console's output image: the EFB copied to the external frame buffer (XFB) as YUYV 4:2:2 by
// GX_CopyDisp, then decoded back to RGB as Dolphin's frame dump does. What the TV shows is the XFB,
// not the EFB; the model is Dolphin 5.0-17995's software renderer (Debian's, an early-2023 build),
// so its frames can be compared with ours bit for bit. Sources, as the rest of gx/ cites them:
// [DSW EfbInterface.cpp EncodeXFB, VerticalFilter, GammaCorrection, ConvertColorToYUV] and
// [DHW TextureDecoder_Common.cpp TexDecoder_DecodeXFB], read in dolphin-emu/dolphin's
// Source/Core/VideoBackends/Software/EfbInterface.cpp as it stood after PR #10466 ("Accurately
// handle the copy filter and gamma for EFB and XFB copies", 2022) and before the 2023 rename to
// SWEfbInterface.cpp (whose EncodeXFB is the same text). Checked against Debian's Dolphin
// itself: its frame dumps of six probe frames equal this model in every pixel (docs/xfb.md).
#pragma once

#include <string>
#include <vector>

#include "gx/efb_copy_state.h"
#include "gx/gx_types.h"

namespace lt::gx {

// One XFB pixel in RAM: its luma and, alternately, the pair's U (even pixel) or V (odd pixel)
// [DSW yuv422_packed].
struct XfbPixel {
  u8 y = 0, uv = 0;
  bool operator==(const XfbPixel&) const = default;
};

// Why an EFB of this size cannot be copied to an XFB (empty when it can): GX_SetDispCopySrc takes
// a width and height that are multiples of 2 [OGC gx.h L3609-3610] - the XFB holds pixel pairs
// sharing one U and one V.
std::string xfb_size_refusal(int width, int height);

// The EFB (RGB8, `width` x `height`, top row first as GX numbers rows) as the copy writes it to
// the XFB: vertical filter, gamma, RGB to YCbCr, chroma filtered [1 2 1]/4 and subsampled.
// LT_CHECKs the size (xfb_size_refusal) and a y scale of 1.
std::vector<XfbPixel> encode_xfb(const std::vector<Color8>& efb, int width, int height,
                                 const EfbCopyState& copy);

// The XFB back to RGB8 (alpha 255) as Dolphin decodes it for display and frame dumps.
std::vector<Color8> decode_xfb(const std::vector<XfbPixel>& xfb, int width, int height);

// decode_xfb(encode_xfb(...)): the picture the TV shows for this EFB.
std::vector<Color8> efb_as_displayed(const std::vector<Color8>& efb, int width, int height,
                                     const EfbCopyState& copy);

}  // namespace lt::gx
