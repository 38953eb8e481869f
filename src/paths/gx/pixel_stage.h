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

// Runs one pass over every covered pixel whose material has a program (by_material[m] null:
// that material draws nothing in this pass) and blends the result into `efb` (row-major, bottom
// row first, like the rasteriser's targets). Returns the TEV stage-pixels run.
size_t shade_pass(const AttributeRasteriser& raster, const std::vector<PixelProgram>& by_material,
                  std::vector<Color8>& efb, bool round_colors);

}  // namespace lt::gx
