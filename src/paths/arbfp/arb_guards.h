// Which of the fragment program's hard-case guards a scene can trigger (issue 10): the
// zero-normal guard (MIN/SGE/MUL of emit_normal, for an interpolated normal below
// kMinNormalLength) only when some triangle's interpolated normal can vanish, that is when the
// origin lies in (or within a margin of) the triangle of its three vertex normals, whose convex
// hull every interpolated normal lies in; a point light's distance-0 guard (the CMP that makes
// L = N at distance 0) only when the light can touch a surface of the material, tested against
// the bounds of its meshes; its attenuation floor (the MAX with kMinAttenuationDenominator) only
// when kc + kl d + kq d^2 can fall below the floor at the distance d the bounds allow. What a
// scene cannot trigger is dropped (the image is the same: each guard changes a pixel only where
// its case occurs), and `info` says why.
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "paths/arbfp/arb_emitters.h"
#include "scene/scene.h"

namespace lt::arbfp {

struct GuardNeeds {
  bool zero_normal = true;
  std::vector<bool> distance_zero;      // per light (false for directional lights)
  std::vector<bool> attenuation_floor;  // per light (false for directional lights)
  std::vector<std::string> notes;       // one per dropped guard, with the figure that allows it
};

// What the guards read of the surfaces drawn with one material: their bounds and the shortest
// interpolated normal. One scan of every triangle, which the lights do not enter: a caller that
// builds programs for several layouts or light subsets of one scene (generate_arb, the pass
// search) scans once and hands the result down.
struct MaterialSurfaces {
  glm::dvec3 lo{std::numeric_limits<double>::infinity()};
  glm::dvec3 hi{-std::numeric_limits<double>::infinity()};
  double shortest_normal = std::numeric_limits<double>::infinity();
  bool empty() const { return lo.x > hi.x; }
};
MaterialSurfaces material_surfaces(const Scene& scene, const Material& material);

// Every guard for `all` (the variant's :guards=all); otherwise those the surfaces of the
// material (material_surfaces of the same scene's objects) can trigger under the scene's lights.
// The notes number the lights by `numbers` (a pass's, arb_passes.h).
GuardNeeds guard_needs(const Scene& scene, const MaterialSurfaces& surfaces, bool all,
                       const LightNumbers& numbers = {});

// The smallest distance from the origin to the triangle (a, b, c), in double.
double distance_to_origin(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

}  // namespace lt::arbfp
