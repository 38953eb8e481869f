#include "image/image.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>

#include "core/error.h"
#include "core/fs.h"

namespace lt {

namespace {
std::string lower_extension(const std::filesystem::path& p) {
  std::string e = p.extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return std::tolower(c); });
  return e;
}
}  // namespace

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
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) throw InputError(path.string(), "", "cannot create image writer");
    bool ok = false;
    if (ext == ".exr") {
      OIIO::ImageSpec spec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT);
      spec.channelnames = {"R", "G", "B", "A"};
      spec.alpha_channel = 3;
      // Linear values, no transfer function: the reference is compared as-is.
      spec.attribute("oiio:ColorSpace", "Linear");
      ok = out->open(tmp.string(), spec) &&
           out->write_image(OIIO::TypeDesc::FLOAT, image.rgba.data());
    } else {
      OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
      std::vector<uint8_t> bytes(image.pixel_count() * 3);
      for (size_t i = 0; i < image.pixel_count(); ++i) {
        for (int c = 0; c < 3; ++c) bytes[i * 3 + c] = to_unorm8(image.rgba[i * 4 + c]);
      }
      ok = out->open(tmp.string(), spec) && out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    }
    if (!ok || !out->close()) {
      throw InputError(path.string(), "", "cannot write image: " + out->geterror());
    }
  });
}

Image read_image(const std::filesystem::path& path) {
  // Before OpenImageIO sees the name: given a FIFO or /dev/zero, its format probing (every
  // reader in turn once the one the extension names has failed) never returns.
  check_input_file(path, InputKind::Image);
  auto in = OIIO::ImageInput::open(path.string());
  if (!in) {
    throw InputError(path.string(), "", "cannot read image: " + OIIO::geterror());
  }
  const OIIO::ImageSpec& spec = in->spec();
  const int channels = spec.nchannels;
  if (spec.width <= 0 || spec.height <= 0 || channels <= 0) {
    throw InputError(path.string(), "", "image has no pixels");
  }
  std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * channels);
  // Reading as FLOAT maps 8-bit v to v/255 exactly, which is what the LSB metrics assume.
  if (!in->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, data.data())) {
    throw InputError(path.string(), "", "cannot decode image: " + in->geterror());
  }
  Image img(spec.width, spec.height);
  const int alpha = spec.alpha_channel;
  for (size_t i = 0; i < img.pixel_count(); ++i) {
    const float* s = &data[i * channels];
    float* d = &img.rgba[i * 4];
    if (channels >= 3) {
      d[0] = s[0], d[1] = s[1], d[2] = s[2];
    } else {
      d[0] = d[1] = d[2] = s[0];
    }
    d[3] = (alpha >= 0 && alpha < channels) ? s[alpha] : 1.0f;
  }
  return img;
}

void flip_vertically(Image& image) {
  const size_t row = static_cast<size_t>(image.width) * 4;
  for (int y = 0; y < image.height / 2; ++y) {
    std::swap_ranges(image.rgba.begin() + y * row, image.rgba.begin() + (y + 1) * row,
                     image.rgba.begin() + (image.height - 1 - y) * row);
  }
}

}  // namespace lt
