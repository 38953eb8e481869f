// The image module (libltrender_imageio.so): ImageCodec over OpenImageIO. The only file that
// includes OpenImageIO; image/image_codec.h says why it is loaded apart from the binary.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>

#include "image/image_codec.h"

namespace lt {
namespace {

class OiioReader final : public ImageFileReader {
 public:
  explicit OiioReader(std::unique_ptr<OIIO::ImageInput> in) : in_(std::move(in)) {
    const OIIO::ImageSpec& s = in_->spec();
    spec_.width = s.width, spec_.height = s.height, spec_.depth = s.depth;
    spec_.channels = s.nchannels, spec_.alpha_channel = s.alpha_channel;
    // Per-channel formats (EXR can mix) report the widest in spec.format; an 8-bit file has one
    // format for all its channels.
    const auto base = static_cast<OIIO::TypeDesc::BASETYPE>(s.format.basetype);
    spec_.is_8bit = base == OIIO::TypeDesc::UINT8 || base == OIIO::TypeDesc::INT8;
    spec_.bits = static_cast<int>(s.format.size()) * 8;
    spec_.floating = base == OIIO::TypeDesc::HALF || base == OIIO::TypeDesc::FLOAT ||
                     base == OIIO::TypeDesc::DOUBLE;
  }
  ~OiioReader() override { close(); }

  const ImageFileSpec& spec() const override { return spec_; }

  bool read_channels(int begin, int end, float* out, std::string& error) override {
    if (in_->read_image(0, 0, begin, end, OIIO::TypeDesc::FLOAT, out)) return true;
    error = in_->geterror();
    return false;
  }

  void close() override {
    if (in_) in_->close();
    in_.reset();
  }

 private:
  std::unique_ptr<OIIO::ImageInput> in_;
  ImageFileSpec spec_;
};

class OiioCodec final : public ImageCodec {
 public:
  std::unique_ptr<ImageFileReader> open(const std::string& path, bool unassociated_alpha,
                                        std::string& error) const override {
    OIIO::ImageSpec config;
    if (unassociated_alpha) config.attribute("oiio:UnassociatedAlpha", 1);
    auto in = OIIO::ImageInput::open(path, &config);
    if (!in) {
      error = OIIO::geterror();
      return nullptr;
    }
    return std::make_unique<OiioReader>(std::move(in));
  }

  bool draw_text(float* rgba, int width, int height, int x, int y, const std::string& text,
                 int size, const std::string& font, const float colour[4]) const override {
    // The caller's pixels as an ImageBuf: render_text draws straight into them.
    OIIO::ImageBuf buf(OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::FLOAT), rgba);
    return OIIO::ImageBufAlgo::render_text(
        buf, x, y, text, size, font, OIIO::cspan<float>(colour, 4),
        OIIO::ImageBufAlgo::TextAlignX::Left, OIIO::ImageBufAlgo::TextAlignY::Top);
  }

  bool text_extent(const std::string& text, int size, const std::string& font, long long& x_begin,
                   long long& x_end) const override {
    const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, size, font);
    if (!r.defined()) return false;
    x_begin = r.xbegin, x_end = r.xend;
    return true;
  }

  void fit_letterbox(const float* rgba, int width, int height, float* out, int out_width,
                     int out_height) const override {
    OIIO::ImageBuf in(OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::FLOAT),
                      const_cast<float*>(rgba));
    const OIIO::ROI roi(0, out_width, 0, out_height, 0, 1, 0, 4);
    // A box filter, its width scaled to the reduction: each thumbnail pixel is the mean of the
    // pixels it covers. fit's default (lanczos3, six lobes of sinf per tap) made the thumbnails
    // of a bench's contact sheet about a tenth of a one-scene quick bench's CPU time (perf);
    // a render or a heatmap reduced for a contact sheet needs no sharper filter than the area
    // mean, and the box has no ringing at the heatmap's colour steps.
    OIIO::ImageBuf small = OIIO::ImageBufAlgo::fit(in, "box", 0.0f, "letterbox", roi);
    small.get_pixels(roi, OIIO::TypeDesc::FLOAT, out);
  }

  std::string library_version() const override {
    // The library's own number (major * 10000 + minor * 100 + patch), not the header's: the
    // version this process runs with.
    const int v = OIIO::openimageio_version();
    return std::to_string(v / 10000) + "." + std::to_string(v / 100 % 100) + "." +
           std::to_string(v % 100);
  }
};

}  // namespace
}  // namespace lt

extern "C" __attribute__((visibility("default"))) const lt::ImageCodec* lt_image_codec() {
  static const lt::OiioCodec codec;
  return &codec;
}
