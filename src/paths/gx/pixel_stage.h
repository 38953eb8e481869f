// The per-pixel half of the GX pipeline, on the CPU: the rasterised channel colours truncated to
// 8 bits, each stage's texture fetch (fixed-point coordinates, 7-bit bilinear), the TEV, the
// alpha test and the EFB blend (gx-hardware.md §5.3 steps 2-5).
#pragma once

#include <array>
#include <vector>

#include "paths/gx/attribute_rasteriser.h"
#include "paths/gx/gx_state.h"

namespace lt::gx {

// One pass's program for the pixels of one material: its state and the texture each map holds
// (the state's own, or the path's LUT where the program loaded none into GX_TEXMAP0).
struct PixelProgram {
  const GxState* state = nullptr;
  std::array<const TextureObject*, kMaxTexMaps> textures{};
};

// The 8-bit value of an interpolated channel colour (0..255 as a float). Real hardware
// interpolates in fixed point of unpublished precision (Dolphin PR#2075: "GC/Wii does
// fixed-point interpolation"); Dolphin's software rasteriser truncates a float [DSW Rasterizer
// Draw]. Truncating the float alone would turn float noise (a flat 200 interpolated as
// 199.99998) into a lost LSB, so the interpolant is first rounded to 8 fractional bits, as a
// fixed-point interpolator with 8 fractional bits would hold it, then truncated. `round`: the
// shader backends' iround(col) instead [DHW tev_ras_table], the other side of gx-hardware.md §2.5.
u8 interpolated_color(float v, bool round = false);

// Runs one pass over every covered pixel whose material has a program (by_material[m] null:
// that material draws nothing in this pass) and blends the result into `efb` (row-major, bottom
// row first, like the rasteriser's targets). Returns the TEV stage-pixels run.
size_t shade_pass(const AttributeRasteriser& raster, const std::vector<PixelProgram>& by_material,
                  std::vector<Color8>& efb, bool round_colors);

}  // namespace lt::gx
