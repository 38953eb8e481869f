// OpenEXR files read and written with the OpenEXR library itself, in this process, without
// loading the image module. The module's load is ~0.35-0.45 s of CPU before it reads a byte
// (image/png_file.h says where it goes); a reference render written as EXR, a `compare` or a
// `regress` against float goldens, a bench run's reference images: each paid it, fifty of the
// test suite's hundred processes that loaded the module (counted with a temporary trace in
// `load_codec`), where the file itself takes milliseconds.
//
// OpenImageIO reads an EXR through this same library: half samples widened to float (exact) and
// float samples as stored, channels R, G, B, A in that order (the file stores them sorted by name,
// A, B, G, R), alpha as stored (EXR's alpha is associated by definition, so OpenImageIO's
// associated-alpha choice changes nothing) [OpenImageIO exrinput.cpp]. This reader does the same
// for the files ltrender writes and most tools write: one part, scan lines, the channels R, G, B
// and optionally A, all half or all float, the data window equal to the display window at the
// origin. Anything else (tiles, deep data, several parts, other channels, windows) is declined
// and the caller loads the module, as open_png declines associated alpha. tests/exr_file_test.cpp
// holds both directions to OpenImageIO bit for bit.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "image/image_codec.h"

namespace lt {

// True when the file starts with OpenEXR's magic number (a file that cannot be read is not).
bool has_exr_signature(const std::filesystem::path& path);

enum class ExrOpen { kOpened, kDeclined, kFailed };

// Opens an EXR for reading. kDeclined (reader null): a kind of EXR this reader leaves to
// OpenImageIO (see above). kFailed: `error` says why, as "EXR read error: <OpenEXR's message>",
// or "header claims WxH pixels, over the limit ..." for any kind of EXR whose data window is over
// kMaxImagePixels (image.h), found from the header before either library allocates for it.
ExrOpen open_exr(const std::string& path, std::unique_ptr<ImageFileReader>& reader,
                 std::string& error);

// Writes float R, G, B, A scan lines, ZIP compressed (OpenImageIO's default for EXR, so a file
// written before this reader existed and one written now differ in no pixel), rows top first.
bool write_exr_rgba_float(const std::string& path, int width, int height, const float* rgba,
                          std::string& error);

}  // namespace lt
