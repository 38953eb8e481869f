// The image library behind one table of functions, loaded on first use. Linked in, OpenImageIO
// made the binary map 271 shared libraries (OpenCV, GDAL, FFmpeg, Poppler ...) and every
// command, `ltrender --help` and a `budget` of one program file included, paid 0.2 s and 180 MB
// before main() (docs/command-line.md "Start-up" has the measurements; issue 11). Only the code in
// image/oiio/ includes OpenImageIO; it is built as the module libltrender_imageio.so, which
// image_codec() loads with dlopen the first time a command reads an image that image/png_file.h
// and image/exr_file.h leave to it, or draws text or thumbnails.
//
// The table passes plain data and error strings, never exceptions: the module has its own copy
// of no ltrender code, so every check, InputError and stderr capture stays in image/.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace lt {

struct ImageFileSpec {
  int width = 0, height = 0, depth = 1, channels = 0;
  int alpha_channel = -1;  // -1: none
  bool is_8bit = false;    // every channel stored as 8-bit integers (PNG); not float or half
  int bits = 8;            // bits per sample (the widest channel's)
  bool floating = false;   // half, float or double samples rather than integers
};

class ImageFileReader {
 public:
  virtual ~ImageFileReader() = default;
  virtual const ImageFileSpec& spec() const = 0;
  // Channels [begin, end) of every pixel as float, row-major, top row first (8-bit v is v/255).
  virtual bool read_channels(int begin, int end, float* out, std::string& error) = 0;
  virtual void close() = 0;
};

class ImageCodec {
 public:
  virtual ~ImageCodec() = default;
  // Null with `error` set when the file cannot be opened as an image. `unassociated_alpha`: the
  // colour channels as stored, not multiplied by alpha (OpenImageIO's default for PNG and TGA).
  virtual std::unique_ptr<ImageFileReader> open(const std::string& path, bool unassociated_alpha,
                                                std::string& error) const = 0;
  // FreeType text through OpenImageIO's render_text into float RGBA pixels.
  virtual bool draw_text(float* rgba, int width, int height, int x, int y, const std::string& text,
                         int size, const std::string& font, const float colour[4]) const = 0;
  // The horizontal extent [x_begin, x_end) the text takes; false when it takes none.
  virtual bool text_extent(const std::string& text, int size, const std::string& font,
                           long long& x_begin, long long& x_end) const = 0;
  // `rgba` (width x height) letterboxed into out_width x out_height (ImageBufAlgo::fit).
  virtual void fit_letterbox(const float* rgba, int width, int height, float* out, int out_width,
                             int out_height) const = 0;
  // The version of the OpenImageIO library the module runs with ("2.4.7"), for --version.
  virtual std::string library_version() const = 0;
};

// The module's one entry point (extern "C", so dlsym finds it by this name).
inline constexpr const char* kImageCodecEntry = "lt_image_codec";
using ImageCodecEntry = const ImageCodec* (*)();

// Loads the module on first use (thread-safe) from the build directory, or an installed binary's
// module folder (core/run_time_files.h). Throws std::runtime_error naming the module and
// dlerror() when it cannot be loaded: an installation fault, not bad input.
const ImageCodec& image_codec();

}  // namespace lt
