#include "paths/arbfp/arb_pass_search.h"

#include <algorithm>

namespace lt::arbfp {

namespace {

struct State {
  size_t points = 0, directionals = 0;
  std::vector<PassShape> passes;  // how it was reached
};

bool dominates(const State& a, const State& b) {
  return a.points >= b.points && a.directionals >= b.directionals;
}

// The states one pass further than `from`: for each number of directional lights, the most
// point lights that fit with them (a program only grows with its lights, so the first that does
// not fit ends the count).
std::vector<State> moves(const State& from, size_t points, size_t directionals, bool first,
                         const PassFits& fits, size_t& most_lights) {
  std::vector<State> out;
  for (size_t b = 0; from.directionals + b <= directionals; ++b) {
    PassShape best;
    bool any = false;
    for (size_t a = 0; from.points + a <= points; ++a) {
      if (a + b == 0) continue;
      const PassShape shape{from.points, a, from.directionals, b};
      if (!fits(shape, first)) break;
      best = shape;
      any = true;
    }
    if (!any) {
      if (b > 0) break;  // b directional lights alone do not fit: more do not either
      continue;
    }
    most_lights = std::max(most_lights, best.lights());
    State next{from.points + best.points, from.directionals + best.directionals, from.passes};
    next.passes.push_back(best);
    out.push_back(std::move(next));
  }
  return out;
}

// The states no other state of the level dominates (the first of equal ones).
std::vector<State> undominated(std::vector<State> states) {
  std::vector<State> out;
  for (size_t i = 0; i < states.size(); ++i) {
    bool dominated = false;
    for (size_t j = 0; j < states.size() && !dominated; ++j) {
      if (j == i || !dominates(states[j], states[i])) continue;
      const bool equal = dominates(states[i], states[j]);
      dominated = !equal || j < i;
    }
    if (!dominated) out.push_back(std::move(states[i]));
  }
  return out;
}

}  // namespace

PassSearch fewest_passes(size_t points, size_t directionals, const PassFits& fits) {
  PassSearch out;
  std::vector<State> level = {State{}};
  for (bool first = true; !level.empty(); first = false) {
    for (const State& s : level) {
      if (s.points == points && s.directionals == directionals) {
        out.passes = s.passes;
        return out;
      }
    }
    std::vector<State> next;
    for (const State& s : level) {
      for (State& m : moves(s, points, directionals, first, fits, out.most_lights)) {
        next.push_back(std::move(m));
      }
    }
    level = undominated(std::move(next));
  }
  return out;  // no pass fits from some state on: a light fits no pass
}

}  // namespace lt::arbfp
