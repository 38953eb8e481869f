// The EFB-to-XFB copy's settings as GX_Init leaves them, in one place: the copy filter (no
// anti-aliasing sample pattern, the vertical filter 0, 0, 21, 22, 21, 0, 0 out of 64), the
// clamp, gamma 1.0 and y scale 1.0. When the XFB copy is modelled (efb_copy_state.h), this
// struct is the one thing to replace with it.
#pragma once

#include <array>

#include "paths/gx/fifo/command_stream.h"

namespace lt::gx::fifo {

struct DisplayCopy {
  // GX_SetCopyFilter(GX_FALSE, NULL, GX_FALSE, NULL): BP 0x01..0x04 = 0x666666 (every sample at
  // the pixel centre, 6 of 12) and the vertical filter 0x53 = 0x595000, 0x54 = 0x15
  // [OGC gx.c L1916-1977].
  std::array<u8, 7> vertical_filter{0, 0, 21, 22, 21, 0, 0};
  u32 sample_pattern = 0x666666;
  u8 clamp = 3;       // GX_SetCopyClamp(GX_CLAMP_TOP | GX_CLAMP_BOTTOM) [OGC gx.c L1905-1909]
  u8 gamma = 0;       // GX_SetDispCopyGamma(GX_GM_1_0) [OGC gx.c L1911-1914]
  u32 y_scale = 256;  // GX_SetDispCopyYScale(1.0): 256 / 1.0 [OGC gx.c GX_SetDispCopyYScale]
};

// What GX_Init sets [OGC gx.c __GX_InitGX].
DisplayCopy gx_init_display_copy();

// BP 0x01..0x04, 0x53, 0x54: filter taps in 6-bit fields at 0, 6, 12, 18 of 0x53 and 0, 6, 12
// of 0x54 [OGC gx.c L1964-1976] [DHW BPMemory.h CopyFilterCoefficients].
void write_copy_filter(CommandStream& out, const DisplayCopy& copy);

// The display copy control without the trigger bits: clamp 0-1, gamma 7-8, scale-invert (y
// scale other than 256) 10, frame-to-field 12-13 = progressive [OGC gx.c L1905-1994]
// [DHW BPMemory.h UPE_Copy].
u32 display_copy_control(const DisplayCopy& copy);

}  // namespace lt::gx::fifo
