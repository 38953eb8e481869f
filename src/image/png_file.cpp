#include "image/png_file.h"

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <vector>

namespace lt {

namespace {

// libpng reports an error by calling this, which must not return: it keeps the message and
// jumps back to the setjmp of the call that failed. Every function below that calls setjmp holds
// only trivially destructible objects across the jump (longjmp skips destructors).
struct PngErrorState {
  char message[256] = {0};
};

[[noreturn]] void on_png_error(png_structp png, png_const_charp message) {
  auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
  std::snprintf(state->message, sizeof state->message, "%s", message ? message : "?");
  png_longjmp(png, 1);
}

// The prefix OpenImageIO's messages had, so a user's logs and scripts read the same.
// Appended piecewise: GCC 12 warns falsely (-Wrestrict) on operator+ after a short literal.
std::string libpng_error(const char* what, const PngErrorState& state) {
  std::string s = what;
  s.append(state.message);
  return s;
}

std::string read_error(const PngErrorState& state) {
  return libpng_error("PNG read error: ", state);
}

std::string naming(const char* what, const std::string& path) {
  std::string s = what;
  s.append(path);
  return s;
}

// libpng's stdio reader says only "Read Error" when a file ends early; this one names the chunk
// it was in ("IDAT: hit end of file"), as OpenImageIO's messages did.
void read_from_file(png_structp png, png_bytep data, size_t length) {
  auto* file = static_cast<std::FILE*>(png_get_io_ptr(png));
  if (std::fread(data, 1, length, file) != length)
    png_chunk_error(png, std::ferror(file) ? "read error" : "hit end of file");
}

class PngReader final : public ImageFileReader {
 public:
  ~PngReader() override { close(); }

  // The header, with OpenImageIO's transforms: palette to RGB, 1/2/4-bit grey to 8 bits and
  // tRNS to an alpha channel (png_set_expand); 16-bit samples in the host's byte order
  // (png_set_swap). No gamma transform: the samples are the file's.
  bool open(const std::string& path, std::string& error) {
    file_ = std::fopen(path.c_str(), "rb");
    if (!file_) {
      error = naming("cannot open ", path);
      return false;
    }
    png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &errors_, on_png_error, nullptr);
    info_ = png_ ? png_create_info_struct(png_) : nullptr;
    if (!png_ || !info_) {
      error = "out of memory for libpng";
      return false;
    }
    if (!read_header()) {
      error = read_error(errors_);
      return false;
    }
    spec_.width = static_cast<int>(png_get_image_width(png_, info_));
    spec_.height = static_cast<int>(png_get_image_height(png_, info_));
    spec_.channels = png_get_channels(png_, info_);
    spec_.bits = png_get_bit_depth(png_, info_);
    spec_.is_8bit = spec_.bits == 8;
    // PNG has alpha only as the last channel of grey-alpha or RGBA [PNG spec 11.2.2].
    spec_.alpha_channel = (spec_.channels == 2 || spec_.channels == 4) ? spec_.channels - 1 : -1;
    return true;
  }

  const ImageFileSpec& spec() const override { return spec_; }

  bool read_channels(int begin, int end, float* out, std::string& error) override {
    if (samples_.empty()) {
      samples_.resize(static_cast<size_t>(png_get_rowbytes(png_, info_)) * spec_.height);
      rows_.resize(static_cast<size_t>(spec_.height));
      const size_t row_bytes = png_get_rowbytes(png_, info_);
      for (int y = 0; y < spec_.height; ++y) rows_[y] = samples_.data() + y * row_bytes;
      if (!read_rows()) {
        samples_.clear();
        error = read_error(errors_);
        return false;
      }
    }
    // OpenImageIO's integer-to-float conversion: v times the reciprocal of the type's maximum,
    // in float [OpenImageIO fmath.h convert_type].
    const size_t pixels = static_cast<size_t>(spec_.width) * spec_.height;
    const int channels = spec_.channels, width = end - begin;
    if (spec_.bits == 16) {
      const auto* v = reinterpret_cast<const uint16_t*>(samples_.data());
      constexpr float kScale = 1.0f / 65535.0f;
      for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < width; ++c) out[p * width + c] = v[p * channels + begin + c] * kScale;
    } else {
      const uint8_t* v = samples_.data();
      constexpr float kScale = 1.0f / 255.0f;
      for (size_t p = 0; p < pixels; ++p)
        for (int c = 0; c < width; ++c) out[p * width + c] = v[p * channels + begin + c] * kScale;
    }
    return true;
  }

  void close() override {
    if (png_) png_destroy_read_struct(&png_, info_ ? &info_ : nullptr, nullptr);
    png_ = nullptr, info_ = nullptr;
    if (file_) std::fclose(file_);
    file_ = nullptr;
  }

 private:
  bool read_header() {
    if (setjmp(png_jmpbuf(png_))) return false;
    png_set_read_fn(png_, file_, read_from_file);
    png_read_info(png_, info_);
    png_set_expand(png_);
    png_set_swap(png_);  // a no-op on 8-bit samples; PNG stores 16-bit ones big-endian
    png_set_interlace_handling(png_);
    png_read_update_info(png_, info_);
    return true;
  }

  bool read_rows() {
    if (setjmp(png_jmpbuf(png_))) return false;
    png_read_image(png_, rows_.data());
    png_read_end(png_, nullptr);
    return true;
  }

  std::FILE* file_ = nullptr;
  png_structp png_ = nullptr;
  png_infop info_ = nullptr;
  PngErrorState errors_;
  ImageFileSpec spec_;
  std::vector<uint8_t> samples_;
  std::vector<png_bytep> rows_;
};

bool write_rows(png_structp png, png_infop info, std::FILE* file, int width, int height,
                int colour_type, png_bytep* rows) {
  if (setjmp(png_jmpbuf(png))) return false;
  png_init_io(png, file);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8,
               colour_type, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  png_write_image(png, rows);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

bool has_png_signature(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  png_byte head[8];
  const bool png = std::fread(head, 1, sizeof head, f) == sizeof head && !png_sig_cmp(head, 0, 8);
  std::fclose(f);
  return png;
}

PngOpen open_png(const std::string& path, bool unassociated_alpha,
                 std::unique_ptr<ImageFileReader>& reader, std::string& error) {
  auto png = std::make_unique<PngReader>();
  if (!png->open(path, error)) return PngOpen::kFailed;
  if (png->spec().alpha_channel >= 0 && !unassociated_alpha) return PngOpen::kDeclined;
  reader = std::move(png);
  return PngOpen::kOpened;
}

namespace {

bool write_png8(const std::string& path, int width, int height, const uint8_t* pixels, int channels,
                std::string& error) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) {
    error = naming("cannot write ", path);
    return false;
  }
  PngErrorState errors;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  std::vector<png_bytep> rows(static_cast<size_t>(height));
  for (int y = 0; y < height; ++y)
    rows[y] = const_cast<png_bytep>(pixels + static_cast<size_t>(y) * width * channels);
  const int colour_type = channels == 4 ? PNG_COLOR_TYPE_RGB_ALPHA : PNG_COLOR_TYPE_RGB;
  const bool ok =
      png && info && write_rows(png, info, file, width, height, colour_type, rows.data());
  if (!ok)
    error = png && info ? libpng_error("PNG write error: ", errors) : "out of memory for libpng";
  png_destroy_write_struct(&png, info ? &info : nullptr);
  const bool closed = std::fclose(file) == 0;
  if (ok && !closed) error = naming("cannot finish writing ", path);
  return ok && closed;
}

}  // namespace

bool write_png_rgb8(const std::string& path, int width, int height, const uint8_t* rgb,
                    std::string& error) {
  return write_png8(path, width, height, rgb, 3, error);
}

bool write_png_rgba8(const std::string& path, int width, int height, const uint8_t* rgba,
                     std::string& error) {
  return write_png8(path, width, height, rgba, 4, error);
}

}  // namespace lt
