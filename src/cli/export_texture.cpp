// `ltrender export texture` (export_texture.h).
#include "cli/export_texture.h"

#include <fstream>
#include <vector>

#include "core/error.h"
#include "core/fs.h"
#include "gx/mip_chain.h"
#include "gx/texture_encoder.h"
#include "gx/tpl_file.h"
#include "image/image.h"

namespace lt::cli {

namespace {

std::string valid_formats() {
  std::string out;
  for (gx::TexFormat f : gx::kAllTexFormats)
    out += (out.empty() ? "" : ", ") + std::string(gx::format_info(f).name);
  return out;
}

}  // namespace

int export_texture(const TextureExportRequest& request) {
  if (!request.format_given)
    throw InputError("export", "--format",
                     "export texture needs --format (" + valid_formats() + ")");
  const std::optional<gx::TexFormat> format = gx::tex_format_from_name(request.format);
  if (!format)
    throw InputError("export", "--format",
                     request.format + ": unknown texture format (valid: " + valid_formats() + ")");
  const std::optional<gx::Rounding> rounding = gx::rounding_from_name(request.rounding);
  if (!rounding)
    throw InputError("export", "--rounding",
                     request.rounding + ": unknown rounding (valid: nearest, truncate)");
  const std::optional<gx::TlutFormat> tlut = gx::tlut_format_from_name(request.tlut);
  if (!tlut)
    throw InputError("export", "--tlut",
                     request.tlut + ": unknown TLUT format (valid: IA8, RGB565, RGB5A3)");
  if (fs::path(request.output).extension() != ".tpl")
    throw InputError(request.output, "", "the exported texture must end in .tpl");
  ensure_not_an_input(request.output, {request.image});
  ImageFileFormat file_format;  // colour as stored, beside an alpha channel (image.h)
  const Image image = read_image(request.image, file_format);
  if (image.width > gx::kMaxTextureSize || image.height > gx::kMaxTextureSize)
    throw InputError(request.image, "",
                     std::to_string(image.width) + "x" + std::to_string(image.height) +
                         " is over the texture unit's 1024 texels a side [OGC gx.h L4263-4264]");
  const gx::Rgba8Image base = gx::rgba8_of(image);
  const int levels = request.mipmaps ? gx::full_mip_levels(base.width, base.height) : 1;
  const std::vector<gx::EncodedLevel> encoded =
      gx::encode_chain(gx::mip_chain(base, levels), *format, {*rounding, *tlut});
  gx::TplTexture t;
  t.format = *format;
  t.width = base.width;
  t.height = base.height;
  t.levels = levels;
  for (const gx::EncodedLevel& level : encoded)
    t.data.insert(t.data.end(), level.data.begin(), level.data.end());
  t.tlut_format = encoded.front().tlut_format;
  t.tlut = encoded.front().tlut;
  if (request.mipmaps) t.min_filter = 5;  // GX_LIN_MIP_LIN, trilinear [OGC gx.h L1005]
  const std::vector<gx::u8> bytes = gx::write_tpl({t});
  write_atomically(request.output, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) throw InputError(request.output, "", "could not be written");
  });
  return 0;
}

}  // namespace lt::cli
