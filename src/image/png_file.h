// PNG files read and written with libpng itself, in this process, without loading the image
// module. Loading OpenImageIO costs a process ~0.45 s of CPU before it reads a byte (the dynamic
// loader binds ~165,000 symbols of the ~270 libraries Debian's build pulls in, OpenVDB's 57,000
// among them: `LD_DEBUG=statistics`, `LD_DEBUG=bindings`, perf), ten times what a 64-pixel gx
// render of a demo scene costs; a regression run, a CI job or the test suite starts hundreds of
// such processes, and nearly all the files they read and write are PNG (docs/command-line.md
// "Start-up").
//
// OpenImageIO's PNG reader is libpng with png_set_expand and png_set_swap, its samples converted
// to float as v * (1 / max) [OpenImageIO png_pvt.h read_info, fmath.h convert_type]: this reader
// does the same, and tests/png_file_test.cpp holds it to OpenImageIO's floats bit for bit on
// every kind of PNG and on real files. One thing it leaves to OpenImageIO: a PNG with alpha read
// with the colour multiplied by alpha (OpenImageIO's associated-alpha default), since that
// product is OpenImageIO's own arithmetic; open_png then declines and the caller loads the module.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "image/image_codec.h"

namespace lt {

// True when the file starts with the eight bytes of the PNG signature (a file that cannot be
// read is not).
bool has_png_signature(const std::filesystem::path& path);

enum class PngOpen { kOpened, kDeclined, kFailed };

// Opens a PNG for reading. kDeclined (reader null): the file has alpha and `unassociated_alpha`
// is false (see above). kFailed: `error` says why, as "PNG read error: <libpng's message>".
PngOpen open_png(const std::string& path, bool unassociated_alpha,
                 std::unique_ptr<ImageFileReader>& reader, std::string& error);

// Writes 8-bit RGB, rows top first, zlib's default compression, no ancillary chunk.
bool write_png_rgb8(const std::string& path, int width, int height, const uint8_t* rgb,
                    std::string& error);
// The same with 8-bit alpha after each pixel's RGB (unassociated, as PNG defines it).
bool write_png_rgba8(const std::string& path, int width, int height, const uint8_t* rgba,
                     std::string& error);

}  // namespace lt
