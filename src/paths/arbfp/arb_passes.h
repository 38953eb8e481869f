// Additive passes that fit a profile (issue 10): when a material's generated programs are over a
// profile (ps_2_0's 64 ALU, 12 temporaries ...), its lights are split into passes, each drawn by
// its own programs: the first pass with the ambient light and depth LESS, the others with depth
// EQUAL, ONE + ONE blending and no depth writes, so the framebuffer sums the passes. The programs
// of each pass are the generator's own for that pass's lights (arb_generator.h).
#pragma once

#include <string>
#include <vector>

#include "budget/arb_profiles.h"
#include "paths/arbfp/arb_generator.h"

namespace lt::arbfp {

struct Pass {
  std::vector<size_t> lights;  // the scene's lights this pass draws, in scene order
  bool ambient = false;        // the scene's ambient light (first pass only)
  ArbPrograms programs;
  budget::ProgramCounts vertex_counts, fragment_counts;
};

struct PassPlan {
  std::string profile;  // empty: no profile, one pass
  std::vector<Pass> passes;
  // How many passes no plan can go below: ceil(lights / the most lights any pass that fits was
  // found to hold). 1 when one pass fits.
  size_t lower_bound = 1;
  size_t most_lights = 0;  // that most (0 when one pass fits)
};

// One pass of every light without a profile, or when the material's programs fit it; otherwise
// the fewest passes whose programs each fit the profile (`profile` names either kind; its
// partner checks the other kind). Lights of both kinds may share a pass in any mix; within a
// kind they are taken in scene order (arb_pass_search.h says why that loses no plan). Throws
// InputError(scene file, "--profile", ...) when a single light does not fit.
PassPlan plan_passes(const Scene& scene, const Material& material, const PowVariant& variant,
                     const std::string& profile);

// "lights 0-4 + ambient" / "light 7" / "lights 0-3, 8, 10", for info, budget and the pass's
// comment.
std::string describe(const Pass& pass);

}  // namespace lt::arbfp
