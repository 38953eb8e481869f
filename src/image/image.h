// The image every path produces: linear float RGBA, top row first. Alpha is coverage (1 where
// geometry was drawn, 0 on the background); it is what the metrics use as the coverage mask.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace lt {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;  // width * height * 4, row-major, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0.0f) {}

  float* at(int x, int y) { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  const float* at(int x, int y) const { return &rgba[(static_cast<size_t>(y) * width + x) * 4]; }
  size_t pixel_count() const { return static_cast<size_t>(width) * height; }
};

// 8-bit conversion of model.md: clamp to [0, 1], then round to nearest (0.5 LSB floor). Also
// the one rounding of every 8-bit table and colour the paths build (LUT texels, cube maps,
// GXColor components), so a path's bytes are the image's bytes for the same value.
// The product is taken in double: in float, 0.7f * 255 rounds up to 178.5 exactly and lands on
// 179, 0.500003 LSB from the value, breaking the 0.5 LSB floor the metrics promise.
inline uint8_t to_unorm8(double v) {
  if (!(v > 0.0)) return 0;  // also maps NaN to 0: a NaN never reaches an 8-bit image
  if (v >= 1.0) return 255;
  return static_cast<uint8_t>(v * 255.0 + 0.5);
}
inline uint8_t to_unorm8(float v) {
  return to_unorm8(static_cast<double>(v));
}

// Writes by extension, atomically (core/fs.h):
//  .exr  float RGBA, unclamped (A = coverage)
//  .png  8-bit RGB of clamp(c, 0, 1) rounded to nearest
// Throws InputError for an unknown extension or an unwritable target.
void write_image(const std::filesystem::path& path, const Image& image);

// Throws InputError unless `path` ends in .png or .exr (checked before any work is done).
void check_output_extension(const std::filesystem::path& path);

// The largest image ltrender makes or reads: the reference's float G-buffer and readbacks take
// ~100 bytes a pixel, so this keeps a render under 2 GB instead of letting a typo exhaust memory.
inline constexpr long long kMaxImagePixels = 4096LL * 4096LL;

// Reads PNG/EXR/anything OpenImageIO reads into linear float RGBA (8-bit values become v/255;
// no alpha channel means fully covered). Throws InputError naming the file, with whatever the
// image libraries printed folded in: for a file that is not regular (core/fs.h), over the image
// size cap, or whose header claims more than kMaxImagePixels (checked before allocating).
Image read_image(const std::filesystem::path& path);

// What a file held before read_image made RGBA of it: for inputs that are data (thickness maps,
// lobe ramps), which must know whether a channel exists and how precise the texels were. This
// form reads the colour channels as stored even beside an alpha channel (OpenImageIO would
// otherwise multiply a PNG's colour by its alpha).
struct ImageFileFormat {
  int colour_channels = 3;  // 1 (grey) or 3: the channels before alpha, at most 3 read
  bool has_alpha = false;
  int bits = 8;           // bits per sample of the file: 8, 16 or 32
  bool floating = false;  // half or float samples (EXR) rather than integers
};
Image read_image(const std::filesystem::path& path, ImageFileFormat& format);

// Whether the file stores 8-bit samples (PNG) rather than float or half (EXR); the same checks
// and errors as read_image.
bool image_file_is_8bit(const std::filesystem::path& path);
// Whether the file has an alpha channel (an EXR from `ltrender render`: its coverage).
bool image_file_has_alpha(const std::filesystem::path& path);

// Flip rows: GL reads bottom row first.
void flip_vertically(Image& image);

}  // namespace lt
