// The per-pixel half of the GX pipeline, on the CPU, for the triangles of one draw in the order
// the console draws them (gx-hardware.md §5.3): for every pixel a triangle covers, the early
// depth test, the texture fetches, the TEV, the alpha test and the EFB blend, in the order of
// Dolphin's software renderer [DSW Rasterizer.cpp Draw, Tev.cpp Tev::Draw, EfbInterface.cpp
// BlendTev].
#pragma once

#include <array>
#include <vector>

#include "gx/efb.h"
#include "gx/gx_state.h"
#include "gx/rasteriser.h"

namespace lt::gx {

// One pass's program for the pixels of one material: its state and the texture each map holds
// (the state's own, or the path's LUT where the program loaded none into GX_TEXMAP0).
struct PixelProgram {
  const GxState* state = nullptr;
  std::array<const TextureObject*, kMaxTexMaps> textures{};
};

// What the pixels of a draw did, for the frame's figures and its warnings.
struct PixelCounts {
  size_t covered = 0;       // pixels the triangles covered
  size_t z_failed = 0;      // of those, failed the depth test
  size_t alpha_failed = 0;  // passed it, failed the alpha test
  size_t written = 0;       // reached the EFB
  size_t stage_pixels = 0;  // TEV stages run
  void add(const PixelCounts& o);
};

// Draws `triangles` (one draw's, in order) with `program` into `efb`. Rows are shared out over
// worker threads in bands; each band draws every triangle that reaches it, in order, so each
// pixel sees the triangles in the console's order whatever the threads do.
// `round_colors`: the :colors=round variant (rasteriser.h).
PixelCounts draw_triangles(const std::vector<Triangle>& triangles, const PixelProgram& program,
                           bool round_colors, Efb& efb);

}  // namespace lt::gx
