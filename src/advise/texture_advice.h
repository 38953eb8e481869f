// advise's texture formats (issue 47): for a console path (gx), each material's pick tried with
// the texture formats a port can ship its maps and its lobe LUT in, each rendered and compared as
// the search measures a candidate, and costed in the frame's texture bytes in MEM1 (texels and
// palettes) and the TMEM one draw's textures occupy, as the path's budget counts them
// (gx_budget.h). The format advised for a material is the one of fewest MEM1 bytes whose error
// on the material stays within the budget (then fewest TMEM bytes, then least error). A second
// step after the pick, as the vertex storage is (storage_advice.h): a format changes the
// textures' bytes and texels, not the TEV program the pick was chosen for.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "metrics/compare.h"
#include "paths/path.h"
#include "scene/scene.h"

namespace lt::advise {

struct TextureOption {
  std::string map_format;  // the :map= value tried ("" the material has no map)
  std::string lut_format;  // the :lut-format= value tried ("" the pick has no LUT)
  std::string variant;     // the pick's variant with them
  std::string failed;      // why it was not measured; empty when it was
  std::size_t texture_bytes = 0, tlut_bytes = 0;  // MEM1, the frame's (budget details)
  std::size_t tmem_bytes = 0;                     // the most one draw's textures occupy
  ErrorStats error;                               // the material's, rendered
  std::size_t non_finite = 0;
  std::size_t mem1_bytes() const { return texture_bytes + tlut_bytes; }
};

struct TextureAdvice {
  std::string maps;  // what the material samples: "grey thickness map", "colour albedo map", ...
  std::vector<TextureOption> options;  // the map formats (with the I8 LUT), then the LUT's
  std::optional<std::size_t> pick;     // fewest MEM1 bytes within the budget
};

// The formats tried for a map of each kind: the default first, then by bytes a texel (the
// formats of the same bytes and fewer bits, RGB5A3, IA8 and IA4, left out, as the grid leaves
// them: docs/textures.md). The LUT: I8 and I4 (IA4 and IA8 hold the same intensities in as many
// or more bytes).
inline constexpr const char* kGreyMapFormats[] = {"i8", "ci8", "i4", "ci4"};
inline constexpr const char* kColourMapFormats[] = {"rgba8", "rgb565", "ci8", "cmpr", "ci4"};
inline constexpr const char* kLutFormats[] = {"i8", "i4"};

struct Advice;

// Fills each material's `textures` (MaterialAdvice) that has a pick and samples a map or the
// lobe LUT, when the path is a console's (writes a FIFO log); renders each distinct variant
// once in a session of its own.
void add_texture_advice(Advice& a, const Scene& scene, const PathInfo& path,
                        const PathOptions& options, const std::string& profile);

}  // namespace lt::advise
