// A rectangle of pixels in GL's window coordinates (row 0 at the bottom, as glReadPixels and
// glScissor count them).
#pragma once

namespace lt::gl {

struct PixelRect {
  int x = 0, y = 0, width = 0, height = 0;

  bool contains(int px, int py) const {
    return px >= x && px < x + width && py >= y && py < y + height;
  }
};

}  // namespace lt::gl
