// Pass plans checked from outside the planner: whether a set of lights fits one pass (the
// generator's programs for exactly those lights against a profile pair), and the fewest passes
// by two independent searches: every partition of the lights (small scenes), and the old
// planner's consecutive runs.
#pragma once

#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include "arb/arb_ir_counter.h"
#include "budget/arb_profiles.h"
#include "paths/arbfp/arb_generator.h"
#include "scene/scene.h"

namespace lt::test {

// Whether `lights` (scene indices), with the ambient light when `first`, fit `profile` and its
// partner in one pass of the default pow=mul programs.
inline bool pass_fits(const Scene& scene, const std::vector<size_t>& lights, bool first,
                      const std::string& profile) {
  Scene sub = scene;
  sub.lights.clear();
  for (size_t i : lights) sub.lights.push_back(scene.lights[i]);
  if (!first) sub.ambient_light = glm::dvec3(0);
  const arbfp::ArbPrograms p =
      arbfp::generate_arb(sub, scene.materials.front(), arbfp::parse_variant("pow=mul"));
  const budget::Profile& chosen = budget::find_profile(profile);
  const budget::Profile& partner = budget::find_profile(chosen.partner);
  return budget::check(arbfp::ir::count(p.fragment_program), chosen).empty() &&
         budget::check(arbfp::ir::count(p.vertex_program), partner).empty();
}

// The fewest passes over every partition of the scene's lights into passes, one of which also
// draws the ambient light: a dynamic programme over subsets (3^n steps), each subset's fit
// decided by generating its programs. Assumes nothing about how programs grow.
inline size_t fewest_passes_by_partition(const Scene& scene, const std::string& profile) {
  const size_t n = scene.lights.size();
  const unsigned all = (1u << n) - 1;
  std::vector<char> fits(all + 1), fits_first(all + 1);
  for (unsigned m = 1; m <= all; ++m) {
    std::vector<size_t> lights;
    for (size_t i = 0; i < n; ++i) {
      if (m & (1u << i)) lights.push_back(i);
    }
    fits[m] = pass_fits(scene, lights, false, profile);
    fits_first[m] = pass_fits(scene, lights, true, profile);
  }
  const size_t none = 1000;
  // rest[m]: fewest passes without ambient for the lights m.
  std::vector<size_t> rest(all + 1, none);
  rest[0] = 0;
  for (unsigned m = 1; m <= all; ++m) {
    for (unsigned s = m; s; s = (s - 1) & m) {
      if (fits[s] && rest[m ^ s] != none) rest[m] = std::min(rest[m], rest[m ^ s] + 1);
    }
  }
  size_t best = none;
  for (unsigned s = all; s; s = (s - 1) & all) {
    if (fits_first[s] && rest[all ^ s] != none) best = std::min(best, rest[all ^ s] + 1);
  }
  return best;
}

// The old planner: consecutive runs, each as long as fits.
inline size_t consecutive_passes(const Scene& scene, const std::string& profile) {
  size_t passes = 0;
  for (size_t first = 0; first < scene.lights.size(); ++passes) {
    std::vector<size_t> run = {first};
    while (first + run.size() < scene.lights.size()) {
      std::vector<size_t> longer = run;
      longer.push_back(first + run.size());
      if (!pass_fits(scene, longer, first == 0, profile)) break;
      run = longer;
    }
    first += run.size();
  }
  return passes;
}

}  // namespace lt::test
