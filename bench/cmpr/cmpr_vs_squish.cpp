// The CMPR encoder (src/gx/cmpr_encoder.h) against libsquish's DXT1 encoder on real images, both
// decoded the console's way (src/gx/texture_decoder.h: 3/8-5/8 blend): one Markdown table row per
// image with the mean and largest absolute error and the RMS error over the r, g and b of every
// opaque texel (alpha >= 128), in 8-bit units. squish runs at its best quality
// (kColourIterativeClusterFit) with a uniform colour metric, the metric the table measures.
// Its DXT1 blocks are converted to GX's CMPR order: endpoints big-endian, each row's texel 0 in
// the top two bits, four blocks an 8x8 tile. An image over 1024 texels a side is halved by the
// mip filter (src/gx/mip_chain.h) until it fits, as a texture converter must.
//
//   scripts/cmpr_vs_squish.sh      (runs this on the glTF sample textures and the demo maps)
//   build/cmpr_vs_squish IMAGE...  (prints the table; exit 1 if ours is worse on any image)
#include <squish.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>

#include "gx/cmpr_encoder.h"
#include "gx/mip_chain.h"
#include "gx/texture_decoder.h"
#include "image/image.h"

namespace {

using lt::gx::Color8;
using lt::gx::Rgba8Image;
using lt::gx::u8;

struct Errors {
  double mean = 0, rms = 0;
  int max = 0;
};

Errors cmpr_errors(const Rgba8Image& image, const std::vector<u8>& cmpr) {
  const lt::gx::TextureView view{lt::gx::TexFormat::CMPR, image.width, image.height, cmpr};
  const std::vector<Color8> decoded = lt::gx::decode_texture(view);
  double sum = 0, sum2 = 0;
  long long n = 0;
  Errors e;
  for (size_t k = 0; k < decoded.size(); ++k) {
    if (image.texels[k].a < 128) continue;
    for (int c = 0; c < 3; ++c) {
      const int d = std::abs(int{decoded[k][c]} - int{image.texels[k][c]});
      sum += d;
      sum2 += double(d) * d;
      e.max = std::max(e.max, d);
      ++n;
    }
  }
  if (n > 0) {
    e.mean = sum / double(n);
    e.rms = std::sqrt(sum2 / double(n));
  }
  return e;
}

// libsquish's DXT1 of every 4x4 block, stored in GX's CMPR order.
std::vector<u8> squish_cmpr(const Rgba8Image& image) {
  std::vector<u8> out(lt::gx::level_bytes(lt::gx::TexFormat::CMPR, image.width, image.height), 0);
  float uniform[3] = {1.0f, 1.0f, 1.0f};
  for (int by = 0; by < image.height; by += 4)
    for (int bx = 0; bx < image.width; bx += 4) {
      u8 rgba[64] = {};
      int mask = 0;
      for (int k = 0; k < 16; ++k) {
        const int x = bx + (k & 3), y = by + (k >> 2);
        if (x >= image.width || y >= image.height) continue;
        const Color8& c = image.at(x, y);
        for (int ch = 0; ch < 4; ++ch) rgba[4 * k + ch] = c[ch];
        mask |= 1 << k;
      }
      u8 dxt[8];
      squish::CompressMasked(rgba, mask, dxt, squish::kDxt1 | squish::kColourIterativeClusterFit,
                             uniform);
      // DXT1: little-endian endpoints, texel x of a row at bits 2x. CMPR: big-endian, 6 - 2x.
      const size_t at = lt::gx::texel_address(lt::gx::TexFormat::CMPR, image.width, bx, by).byte;
      out[at] = dxt[1];
      out[at + 1] = dxt[0];
      out[at + 2] = dxt[3];
      out[at + 3] = dxt[2];
      for (int row = 0; row < 4; ++row) {
        int bits = 0;
        for (int x = 0; x < 4; ++x) bits |= ((dxt[4 + row] >> (2 * x)) & 3) << (6 - 2 * x);
        out[at + 4 + static_cast<size_t>(row)] = static_cast<u8>(bits);
      }
    }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: %s IMAGE...\n", argv[0]);
    return 2;
  }
  std::printf(
      "| image | size | ours mean | ours max | ours RMS | squish mean | squish max | "
      "squish RMS |\n|---|---|---|---|---|---|---|---|\n");
  bool worse = false;
  for (int i = 1; i < argc; ++i) {
    try {
      lt::ImageFileFormat format;
      Rgba8Image image = lt::gx::rgba8_of(lt::read_image(argv[i], format));
      while (image.width > lt::gx::kMaxTextureSize || image.height > lt::gx::kMaxTextureSize)
        image = lt::gx::box_filter_half(image);
      const Errors ours = cmpr_errors(image, lt::gx::encode_cmpr(image).data);
      const Errors theirs = cmpr_errors(image, squish_cmpr(image));
      worse = worse || ours.mean > theirs.mean;
      std::printf("| %s | %dx%d | %.3f | %d | %.3f | %.3f | %d | %.3f |\n", argv[i], image.width,
                  image.height, ours.mean, ours.max, ours.rms, theirs.mean, theirs.max, theirs.rms);
      std::fflush(stdout);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", argv[i], e.what());
      return 2;
    }
  }
  return worse ? 1 : 0;
}
