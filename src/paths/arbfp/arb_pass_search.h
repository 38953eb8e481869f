// The fewest passes for a material's lights (arb_passes.h), as a search over how many lights of
// each kind every pass takes. Point and directional lights are the two kinds: a packed group
// holds lights of one kind, so a pass's program depends on its mix, and consecutive runs of a
// mixed scene can need more passes than a plan that mixes the kinds differently.
//
// Within a kind, lights are taken in scene order: pass k takes the next a_k point lights and
// the next b_k directional ones. That loses no plan as long as lights of one kind cost the same
// in a program (the generator emits the same instructions for every light of a kind; only a
// guard a light needs, arb_guards.h, adds a CMP or MAX to its lane) and a program only grows
// with its lights. Under those two facts the search is exact: breadth first over the states
// (point lights taken, directional lights taken), each pass's moves the largest a for every b,
// states another state dominates (at least as many of both kinds taken) dropped. Every state of
// a level is reached with that many passes, so the first level holding (all, all) is the fewest.
// tests/arb_pass_test.cpp checks it against every partition of small scenes.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace lt::arbfp {

// A pass of point lights [point, point + points) and directional lights [directional,
// directional + directionals), counted in each kind's scene order.
struct PassShape {
  size_t point = 0, points = 0, directional = 0, directionals = 0;
  size_t lights() const { return points + directionals; }
};

// Whether the pass's programs fit; `first`: the pass also draws the ambient light.
using PassFits = std::function<bool(const PassShape&, bool first)>;

struct PassSearch {
  std::vector<PassShape> passes;  // empty: some light fits no pass
  size_t most_lights = 0;         // the most lights of any pass found to fit
};

PassSearch fewest_passes(size_t points, size_t directionals, const PassFits& fits);

}  // namespace lt::arbfp
