// The state of the EFB-to-XFB copy (GX_CopyDisp): what the copy does to the EFB on its way to the
// external frame buffer the video interface shows. Fields are named after the registers they live
// in, so the DFF encoder writes this struct as it stands; the defaults are what libogc's GX_Init
// leaves [OGC gx.c __GX_InitGX L724-729], and nothing ltrender exports changes them.
#pragma once

#include <array>

#include "gx/gx_types.h"

namespace lt::gx {

// GX_GM_1_0, GX_GM_1_7, GX_GM_2_2 [OGC gx.h L941-943]: the copy's gamma field (BP 0x52 bits 7-8,
// GX_SetDispCopyGamma [OGC gx.c L1911-1914]).
inline constexpr u8 kGamma1_0 = 0, kGamma1_7 = 1, kGamma2_2 = 2;

// GX_SetDispCopyYScale(1.0) writes 256.0 / 1.0 into BP 0x4E [OGC gx.c L1984-1994].
inline constexpr u16 kYScaleOne = 256;

struct EfbCopyState {
  // The seven vertical filter coefficients (6 bits each), BP 0x53 bits 0-23 (w0..w3) and BP 0x54
  // bits 0-17 (w4..w6) [OGC gx.c GX_SetCopyFilter L1965-1976; Dolphin VideoCommon/BPMemory.h
  // CopyFilterCoefficients]. GX_SetCopyFilter(GX_FALSE, NULL, GX_FALSE, NULL) writes 0x595000 and
  // 0x000015, i.e. {0, 0, 21, 22, 21, 0, 0}: all 64 on the current line, none on the lines above
  // and below - the filter is an identity.
  std::array<u8, 7> vertical_filter = {0, 0, 21, 22, 21, 0, 0};
  // GX_SetCopyClamp(GX_CLAMP_TOP | GX_CLAMP_BOTTOM): BP 0x52 bits 0 and 1 [OGC gx.c L1905-1909].
  bool clamp_top = true, clamp_bottom = true;
  u8 gamma = kGamma1_0;  // GX_SetDispCopyGamma(GX_GM_1_0)
  u16 y_scale = kYScaleOne;

  bool operator==(const EfbCopyState&) const = default;
};

}  // namespace lt::gx
