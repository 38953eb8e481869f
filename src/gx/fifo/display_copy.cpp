#include "gx/fifo/display_copy.h"

#include "gx/fifo/bp_registers.h"

namespace lt::gx::fifo {

void write_copy_filter(CommandStream& out, const EfbCopyState& c) {
  for (int i = 0; i < 4; ++i)
    out.load_bp(static_cast<u8>(bp::kCopyFilterPattern0 + i), kCentredSamplePattern);
  const auto& f = c.vertical_filter;
  out.load_bp(bp::kCopyFilter0,
              place(f[0], 0, 6) | place(f[1], 6, 6) | place(f[2], 12, 6) | place(f[3], 18, 6));
  out.load_bp(bp::kCopyFilter1, place(f[4], 0, 6) | place(f[5], 6, 6) | place(f[6], 12, 6));
}

u32 display_copy_control(const EfbCopyState& c) {
  return place(c.clamp_top, 0, 1) | place(c.clamp_bottom, 1, 1) | place(c.gamma, 7, 2) |
         place(c.y_scale != kYScaleOne, 10, 1);
}

}  // namespace lt::gx::fifo
