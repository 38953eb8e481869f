#include "image/text.h"

#include "image/image_codec.h"

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
  const float colour[4] = {rgb[0], rgb[1], rgb[2], 1.0f};
  return image_codec().draw_text(image.rgba.data(), image.width, image.height, x, y, text, size,
                                 label_font().string(), colour);
}

int text_width(const std::string& text, int size) {
  if (text.empty()) return 0;
  if (label_font().empty()) return static_cast<int>(text.size() * size * 6 / 10);
  long long x_begin = 0, x_end = 0;
  // text_size can return extents with xend < xbegin (nothing drawn, e.g. only spaces), whose
  // ROI::width() overflows int (UBSan): take the width in 64 bits and clamp.
  if (!image_codec().text_extent(text, size, label_font().string(), x_begin, x_end)) return 0;
  const long long w = x_end - x_begin;
  return w > 0 && w < (1LL << 30) ? static_cast<int>(w) : 0;
}

}  // namespace lt
