#include "image/image.h"

#include <algorithm>
#include <memory>
#include <new>

#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "core/stderr_capture.h"
#include "image/exr_file.h"
#include "image/image_codec.h"
#include "image/png_file.h"

namespace lt {

void check_output_extension(const std::filesystem::path& path) {
  const std::string ext = lower_extension(path);
  if (ext != ".exr" && ext != ".png") {
    throw InputError(path.string(), "", "unsupported output format (use .png or .exr)");
  }
}

void write_image(const std::filesystem::path& path, const Image& image) {
  check_output_extension(path);
  const std::string ext = lower_extension(path);
  write_atomically(path, [&](const fs::path& tmp) {
    std::string error;
    bool ok = false;
    if (ext == ".exr") {
      // OpenEXR in this process: no image module to load (image/exr_file.h).
      ok = write_exr_rgba_float(tmp.string(), image.width, image.height, image.rgba.data(), error);
    } else {
      std::vector<uint8_t> bytes(image.pixel_count() * 3);
      for (size_t i = 0; i < image.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) bytes[i * 3 + c] = to_unorm8(image.rgba[i * 4 + c]);
      }
      // libpng in this process: no image module to load (image/png_file.h).
      ok = write_png_rgb8(tmp.string(), image.width, image.height, bytes.data(), error);
    }
    if (!ok) throw InputError(path.string(), "", "cannot write image: " + error);
  });
}

namespace {

// "WxH", or "WxHxD" for a volume. Appended piecewise: GCC 12 warns falsely (-Wrestrict) on a
// chained operator+ starting with a short literal.
std::string dimensions_text(const ImageFileSpec& spec) {
  std::string s = std::to_string(spec.width);
  s.append("x").append(std::to_string(spec.height));
  if (spec.depth > 1) s.append("x").append(std::to_string(spec.depth));
  return s;
}

// An image file opened for reading, with the capture of what its libraries print on the side.
// Every failure folds that text into the one InputError (cli.md's one line).
class CheckedInput {
 public:
  // `unassociated_alpha`: the colour channels as the file stores them. Without it OpenImageIO
  // multiplies a PNG's or TGA's colour by its alpha (its "associated alpha" convention), which a
  // data texture (a thickness map with a mask in alpha) must not have.
  explicit CheckedInput(const fs::path& path, bool unassociated_alpha = false) : path_(path) {
    // Before OpenImageIO sees the name: given a FIFO or /dev/zero, its format probing (every
    // reader in turn once the one the extension names has failed) never returns.
    check_input_file(path, InputKind::Image);
    std::string error;
    // A PNG is read with libpng and a plain EXR with OpenEXR in this process, unless it needs
    // OpenImageIO's associated alpha or is an EXR of another kind (image/png_file.h,
    // image/exr_file.h); anything else through the image module.
    bool declined = true;
    if (has_png_signature(path))
      declined = open_png(path.string(), unassociated_alpha, in_, error) == PngOpen::kDeclined;
    else if (has_exr_signature(path))
      declined = open_exr(path.string(), in_, error) == ExrOpen::kDeclined;
    if (declined) in_ = image_codec().open(path.string(), unassociated_alpha, error);
    if (!in_) fail("cannot read image: " + error);
    const ImageFileSpec& spec = in_->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.channels <= 0) fail("image has no pixels");
    // The header's size is checked before any pixel is allocated: 65 bytes of PNG can claim
    // 40000 x 40000 pixels (13.7 GB as float RGB).
    const long long pixels = static_cast<long long>(spec.width) * spec.height;
    if (pixels > kMaxImagePixels || spec.depth > 1) {
      fail("header claims " + dimensions_text(spec) + " pixels, over the limit of " +
           std::to_string(kMaxImagePixels) + " (4096^2) pixels");
    }
  }
  ~CheckedInput() {
    if (in_) in_->close();  // libraries may still print while closing: inside the capture
  }
  CheckedInput(const CheckedInput&) = delete;
  CheckedInput& operator=(const CheckedInput&) = delete;

  const ImageFileSpec& spec() const { return in_->spec(); }

  // Channels [begin, end) of every pixel as float (8-bit v becomes v/255 exactly, which is what
  // the LSB metrics assume).
  std::vector<float> read_channels(int begin, int end) {
    std::vector<float> data(static_cast<size_t>(spec().width) * spec().height * (end - begin));
    std::string error;
    if (!in_->read_channels(begin, end, data.data(), error)) fail("cannot decode image: " + error);
    return data;
  }

  [[noreturn]] void fail(const std::string& what) {
    throw InputError(path_.string(), "", capture_.fold_into(what));
  }

 private:
  const fs::path& path_;
  StderrCapture capture_;  // declared before in_: it outlives the reader's close
  std::unique_ptr<ImageFileReader> in_;
};

}  // namespace

namespace {

Image read_image_unguarded(const std::filesystem::path& path, ImageFileFormat* format) {
  CheckedInput in(path, format != nullptr);
  const ImageFileSpec& spec = in.spec();
  if (format) {
    format->bits = spec.bits;
    format->floating = spec.floating;
    format->has_alpha = spec.alpha_channel >= 0 && spec.alpha_channel < spec.channels;
    format->colour_channels = spec.channels >= 3 ? 3 : 1;  // as the copy below reads them
  }
  // At most four channels are read (grey or RGB, then alpha): memory stays 16 bytes a pixel
  // whatever number of channels the file declares.
  const int channels = std::min(spec.channels, 4);
  const std::vector<float> data = in.read_channels(0, channels);
  const int alpha = spec.alpha_channel;
  std::vector<float> far_alpha;  // an alpha channel beyond the first four, read on its own
  if (alpha >= channels && alpha < spec.channels) far_alpha = in.read_channels(alpha, alpha + 1);
  Image img(spec.width, spec.height);
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    const float* s = &data[i * channels];
    float* d = &img.rgba[i * 4];
    if (channels >= 3) {
      d[0] = s[0], d[1] = s[1], d[2] = s[2];
    } else {
      d[0] = d[1] = d[2] = s[0];
    }
    if (!far_alpha.empty()) {
      d[3] = far_alpha[i];
    } else {
      d[3] = (alpha >= 0 && alpha < channels) ? s[alpha] : 1.0f;
    }
  }
  return img;
}

}  // namespace

namespace {
Image read_image_checked(const std::filesystem::path& path, ImageFileFormat* format) {
  try {
    return read_image_unguarded(path, format);
  } catch (const std::bad_alloc&) {
    // Within the pixel limit but too large for the memory left: name the file.
    throw InputError(path.string(), "", "out of memory reading this image");
  }
}
}  // namespace

Image read_image(const std::filesystem::path& path) {
  return read_image_checked(path, nullptr);
}

Image read_image(const std::filesystem::path& path, ImageFileFormat& format) {
  return read_image_checked(path, &format);
}

bool image_file_is_8bit(const std::filesystem::path& path) {
  CheckedInput in(path);
  return in.spec().is_8bit;
}

bool image_file_has_alpha(const std::filesystem::path& path) {
  CheckedInput in(path);
  return in.spec().alpha_channel >= 0 && in.spec().alpha_channel < in.spec().channels;
}

void flip_vertically(Image& image) {
  const size_t row = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < image.height / 2; ++y) {
    std::swap_ranges(image.rgba.begin() + y * row, image.rgba.begin() + (y + 1) * row,
                     image.rgba.begin() + (image.height - 1 - y) * row);
  }
}

}  // namespace lt
