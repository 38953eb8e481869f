// The variants `advise` searches for one path: every axis of the path's typed variant key
// (arbfp::PowVariant, gx::GxVariant, the combiners' three plans) over a grid, each candidate with
// the texture bytes its lobe needs, the second cost figure after the work axis (a bigger LUT
// costs no instruction more, only memory). Axes that are not a porter's choice (which of two
// emulations of one piece of hardware, which image the path returns) are left out, with why.
#pragma once

#include <string>
#include <vector>

#include "paths/path.h"
#include "scene/scene.h"

namespace lt::advise {

struct Candidate {
  std::string variant;  // canonical name, as --variant takes it
  // The texture bytes the variant's lobe needs per translucent material (LUT texels x bytes a
  // texel, or the combiners' cube maps); a material without translucency pays none.
  double texture_bytes = 0;
  // Non-empty: the same image as `same_image_as` from a program that is never cheaper (a
  // superset of its instructions); searched only when pruning is off.
  std::string never_cheaper, same_image_as;
};

struct VariantSpace {
  std::vector<Candidate> candidates;  // the path's default first
  std::vector<std::string> left_out;  // axes not searched, each with why
};

// The LUT widths searched on every LUT axis (arbfp pow=lut, gx lut=N): powers of two from 8 to
// the 1024 texels a GX texture side takes [OGC gx.h L4263].
inline constexpr int kLutWidths[] = {8, 16, 32, 64, 128, 256, 512, 1024};

// Throws LT_CHECK for a path advise has no space for (find_target only hands out arbfp,
// combiners and gx).
VariantSpace variant_space(const PathInfo& path, const Scene& scene);

}  // namespace lt::advise
