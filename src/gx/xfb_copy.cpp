#include "gx/xfb_copy.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

// Dolphin citations: [DSW f] is function f of Source/Core/VideoBackends/Software/EfbInterface.cpp
// (the copy), [DHW TexDecoder_DecodeXFB] is VideoCommon/TextureDecoder_Common.cpp (the display and
// frame-dump side: the software backend copies the XFB to RAM and the texture cache decodes it from
// there on the CPU). Float expressions keep Dolphin's operand order and float type: ltrender is
// built, as Debian builds Dolphin, for baseline x86-64 without FMA, so nothing is fused.

namespace lt::gx {

namespace {

// Per pixel, before the chroma filter: luma 0..219 and chroma -112..112, not yet offset
// [DSW yuv444, "a non-normalized value, which saves work later"].
struct Yuv444 {
  int y = 0, u = 0, v = 0;
};

// min(255, (above*(w0+w1) + here*(w2+w3+w4) + below*(w5+w6)) >> 6) per channel: in
// non-multisampled mode coefficients 0-1 weigh the line above, 2-4 this line, 5-6 the line below
// [DSW VerticalFilter]. GX_Init's {0,0,21,22,21,0,0} makes it 64*here >> 6 = here.
Color8 vertical_filter(const Color8& above, const Color8& here, const Color8& below,
                       const std::array<u8, 7>& w) {
  Color8 out;
  for (int ch = 0; ch < 3; ++ch) {
    const int sum =
        above[ch] * (w[0] + w[1]) + here[ch] * (w[2] + w[3] + w[4]) + below[ch] * (w[5] + w[6]);
    out[ch] = static_cast<u8>(std::min(255, sum >> 6));
  }
  return out;
}

// pow(c / 255, 1 / gamma) * 255 in float, clamped and truncated [DSW GammaCorrection], gamma from
// the field's table 1.0, 1.7, 2.2 [DHW BPStructs.cpp s_gammaLUT]. For gamma 1.0 this is the
// identity on every byte (a float x/255*255 never falls below x there).
Color8 gamma_correct(const Color8& c, u8 gamma) {
  static constexpr float kGamma[] = {1.0f, 1.7f, 2.2f};
  LT_CHECK(gamma <= kGamma2_2, "copy gamma field " + std::to_string(gamma) + " is not a GX_GM_*");
  const float gamma_rcp = 1.0f / kGamma[gamma];
  Color8 out;
  for (int ch = 0; ch < 3; ++ch) {
    const float v = std::pow(c[ch] / 255.0f, gamma_rcp) * 255.0f;
    out[ch] = static_cast<u8>(std::clamp(v, 0.0f, 255.0f));
  }
  return out;
}

// BT.601 with the hardware-tested integer weights, divided by 256 rounding half up
// [DSW ConvertColorToYUV: "These numbers were determined by hardware testing"]. The sums fit the
// u16/s16 Dolphin keeps them in (|u|, |v| <= 112*255), so no wrap; >> on a negative value is the
// arithmetic shift (C++20), as on Dolphin's compilers.
Yuv444 to_yuv(const Color8& c) {
  const int y = 66 * c.r + 129 * c.g + 25 * c.b;
  const int u = -38 * c.r - 74 * c.g + 112 * c.b;
  const int v = 112 * c.r - 94 * c.g - 18 * c.b;
  auto round = [](int s) { return (s >> 8) + ((s >> 7) & 1); };
  return {round(y), round(u), round(v)};
}

// One decoded channel: truncated toward zero, then clamped [DHW TexDecoder_DecodeXFB].
u8 to_channel(float v) {
  return static_cast<u8>(std::clamp(static_cast<int>(v), 0, 255));
}

}  // namespace

std::string xfb_size_refusal(int width, int height) {
  if (width % 2 == 0 && height % 2 == 0) return "";
  return "the XFB copy needs an even width and height (GX_SetDispCopySrc takes multiples of 2 "
         "pixels: the XFB stores pixel pairs that share one U and one V), not " +
         std::to_string(width) + "x" + std::to_string(height);
}

std::vector<XfbPixel> encode_xfb(const std::vector<Color8>& efb, int width, int height,
                                 const EfbCopyState& copy) {
  LT_CHECK(xfb_size_refusal(width, height).empty(), xfb_size_refusal(width, height));
  LT_CHECK(efb.size() == static_cast<size_t>(width) * height, "EFB size does not match");
  LT_CHECK(copy.y_scale == kYScaleOne, "only a y scale of 1 (GX_Init's) is modelled");
  const auto& w = copy.vertical_filter;
  std::vector<XfbPixel> xfb(efb.size());
  // Chroma of one line with a pixel of border each side: Flipper repeats the edge pixels
  // [DSW EncodeXFB "Flipper clamps the border colors"].
  std::vector<Yuv444> line(static_cast<size_t>(width) + 2);
  for (int y = 0; y < height; ++y) {
    // The lines the filter reads above and below. The copy rectangle starts at EFB line 0, so the
    // line above line 0 is line 0 whether or not the top is clamped [DSW EncodeXFB: y_prev =
    // max(clamp_top ? top : 0, y - 1)]. Below the last line an unclamped copy reads EFB memory
    // outside the frame ("random garbage" on hardware, the next EFB line in Dolphin): only
    // modelled where that line weighs nothing.
    const int above = std::max(0, y - 1);
    const int below = std::min(height - 1, y + 1);
    LT_CHECK(copy.clamp_bottom || y + 1 < height || w[5] + w[6] == 0,
             "an unclamped bottom line with a weight below it reads outside the EFB");
    for (int x = 0; x < width; ++x) {
      auto at = [&](int row) { return efb[static_cast<size_t>(row) * width + x]; };
      const Color8 filtered = vertical_filter(at(above), at(y), at(below), w);
      line[static_cast<size_t>(x) + 1] = to_yuv(gamma_correct(filtered, copy.gamma));
    }
    line.front() = line[1];
    line.back() = line[static_cast<size_t>(width)];
    XfbPixel* out = &xfb[static_cast<size_t>(y) * width];
    // Each pair (x, x+1) keeps both lumas; its U and its V are both filtered [1 2 1]/4 around the
    // even pixel x (line index i = x + 1), with an arithmetic shift (a floor), then offset by 128
    // and the luma by 16 [DSW EncodeXFB, the "Downsample them to 4:2:2" loop].
    for (int x = 0; x < width; x += 2) {
      const size_t i = static_cast<size_t>(x) + 1;
      const int u = (line[i - 1].u + (line[i].u << 1) + line[i + 1].u) >> 2;
      const int v = (line[i - 1].v + (line[i].v << 1) + line[i + 1].v) >> 2;
      out[x] = {static_cast<u8>(line[i].y + 16), static_cast<u8>(128 + u)};
      out[x + 1] = {static_cast<u8>(line[i + 1].y + 16), static_cast<u8>(128 + v)};
    }
  }
  return xfb;
}

std::vector<Color8> decode_xfb(const std::vector<XfbPixel>& xfb, int width, int height) {
  LT_CHECK(width % 2 == 0 && xfb.size() == static_cast<size_t>(width) * height,
           "XFB size does not match");
  std::vector<Color8> rgb(xfb.size());
  for (size_t p = 0; p < xfb.size(); p += 2) {
    // Small integers, exact in float: the same operands Dolphin's int-to-float promotion gives.
    const auto f = [](int i) { return static_cast<float>(i); };
    const float u = f(xfb[p].uv - 128), v = f(xfb[p + 1].uv - 128);
    for (size_t k = 0; k < 2; ++k) {
      // The inverse BT.601 with Dolphin's rounded constants, in float [DHW TexDecoder_DecodeXFB].
      const float y = f(xfb[p + k].y - 16);
      rgb[p + k] = {to_channel(1.164f * y + 1.596f * v),
                    to_channel(1.164f * y - 0.392f * u - 0.813f * v),
                    to_channel(1.164f * y + 2.017f * u), 255};
    }
  }
  return rgb;
}

std::vector<Color8> efb_as_displayed(const std::vector<Color8>& efb, int width, int height,
                                     const EfbCopyState& copy) {
  return decode_xfb(encode_xfb(efb, width, height, copy), width, height);
}

}  // namespace lt::gx
