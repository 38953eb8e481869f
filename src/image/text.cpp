#include "image/text.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <vector>

namespace lt {

const std::filesystem::path& label_font() {
  static const std::filesystem::path found = [] {
    for (const char* p :
         {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf",
          "/usr/share/fonts/dejavu/DejaVuSans.ttf"}) {
      std::error_code ec;
      if (std::filesystem::is_regular_file(p, ec)) return std::filesystem::path(p);
    }
    return std::filesystem::path();
  }();
  return found;
}

bool draw_text(Image& image, int x, int y, const std::string& text, int size, const float rgb[3]) {
  if (label_font().empty() || text.empty()) return !label_font().empty();
  // The image's own pixels as an ImageBuf: render_text draws straight into them.
  OIIO::ImageBuf buf(OIIO::ImageSpec(image.width, image.height, 4, OIIO::TypeDesc::FLOAT),
                     image.rgba.data());
  const float colour[4] = {rgb[0], rgb[1], rgb[2], 1.0f};
  return OIIO::ImageBufAlgo::render_text(buf, x, y, text, size, label_font().string(), colour,
                                         OIIO::ImageBufAlgo::TextAlignX::Left,
                                         OIIO::ImageBufAlgo::TextAlignY::Top);
}

int text_width(const std::string& text, int size) {
  if (text.empty()) return 0;
  if (label_font().empty()) return static_cast<int>(text.size() * size * 6 / 10);
  const OIIO::ROI r = OIIO::ImageBufAlgo::text_size(text, size, label_font().string());
  // text_size can return extents with xend < xbegin (nothing drawn, e.g. only spaces), whose
  // ROI::width() overflows int (UBSan): take the width in 64 bits and clamp.
  if (!r.defined()) return 0;
  const long long w = static_cast<long long>(r.xend) - r.xbegin;
  return w > 0 && w < (1LL << 30) ? static_cast<int>(w) : 0;
}

}  // namespace lt
