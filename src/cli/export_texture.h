// `ltrender export texture IMAGE --format FMT [--mipmaps] [--rounding R] [--tlut T] -o FILE.tpl`
// (docs/textures.md): one image encoded to a GX texture format as a porter's converter would,
// written as a libogc TPL file, so the encoders can be used and checked on their own.
#pragma once

#include <string>

namespace lt::cli {

struct TextureExportRequest {
  std::string image;   // PNG, EXR, JPEG ... through the image layer
  std::string format;  // I4 .. CMPR (texture_format.h names; GX_TF_ prefix allowed)
  bool format_given = false;
  std::string rounding = "nearest";  // or "truncate" (gxtexconv's)
  std::string tlut = "RGB565";       // CI4, CI8, CI14X2: IA8, RGB565 or RGB5A3
  bool mipmaps = false;              // the full chain down to 1x1, box filtered
  std::string output;                // FILE.tpl
};

// Exit code 0; bad input throws InputError naming the file or option, nothing written.
int export_texture(const TextureExportRequest& request);

}  // namespace lt::cli
