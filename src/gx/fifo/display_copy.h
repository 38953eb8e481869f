// The EFB-to-XFB copy's registers, written from the one copy state the XFB model reads
// (efb_copy_state.h: GX_Init's copy filter, clamp, gamma and y scale), so the frame Dolphin
// plays and the `:out=xfb` picture ltrender computes come from the same settings.
#pragma once

#include "gx/efb_copy_state.h"
#include "gx/fifo/command_stream.h"

namespace lt::gx::fifo {

// GX_SetCopyFilter(GX_FALSE, NULL, ...) sets no anti-aliasing: every one of the 12 sample
// positions at the pixel centre, 6 of 12, in BP 0x01..0x04 [OGC gx.c L1916-1963]. The XFB model
// does not read it (the EFB is not multisampled), so it is not part of EfbCopyState.
inline constexpr u32 kCentredSamplePattern = 0x666666;

// BP 0x01..0x04, 0x53, 0x54: filter taps in 6-bit fields at 0, 6, 12, 18 of 0x53 and 0, 6, 12
// of 0x54 [OGC gx.c L1964-1976] [DHW BPMemory.h CopyFilterCoefficients].
void write_copy_filter(CommandStream& out, const EfbCopyState& copy);

// The display copy control without the trigger bits: clamp 0-1, gamma 7-8, scale-invert (y
// scale other than 256) 10, frame-to-field 12-13 = progressive [OGC gx.c L1905-1994]
// [DHW BPMemory.h UPE_Copy].
u32 display_copy_control(const EfbCopyState& copy);

}  // namespace lt::gx::fifo
