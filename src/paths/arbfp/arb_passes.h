// Additive passes that fit a profile (issue 10): when a material's generated programs are over a
// profile (ps_2_0's 64 ALU, 12 temporaries ...), its lights are split into consecutive runs, each
// drawn by its own programs: the first pass with the ambient light and depth LESS, the others
// with depth EQUAL, ONE + ONE blending and no depth writes, so the framebuffer sums the passes.
// The programs of each pass are the generator's own for that run of lights (arb_generator.h).
#pragma once

#include <string>
#include <vector>

#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_profiles.h"

namespace lt::arbfp {

struct Pass {
  size_t first = 0, count = 0;  // the scene's lights first .. first + count - 1
  bool ambient = false;         // the scene's ambient light (first pass only)
  ArbPrograms programs;
  budget::ProgramCounts vertex_counts, fragment_counts;
};

struct PassPlan {
  std::string profile;  // empty: no profile, one pass
  std::vector<Pass> passes;
};

// One pass of every light without a profile, or when the material's programs fit it; otherwise
// the fewest passes of consecutive lights whose programs each fit the profile (`profile` names
// either kind; its partner checks the other kind). Greedy: each pass takes as many lights as
// fit, which is the fewest passes of consecutive lights because a run's programs only grow with
// its lights. Throws InputError(scene file, "--profile", ...) when a single light does not fit.
PassPlan plan_passes(const Scene& scene, const Material& material, const PowVariant& variant,
                     const std::string& profile);

// "lights 0-4 + ambient" / "light 7", for info, budget and the pass's comment.
std::string describe(const Pass& pass);

}  // namespace lt::arbfp
