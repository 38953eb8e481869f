#include "paths/arbfp/arb_generator.h"

#include <utility>

#include "arb/arb_ir_counter.h"
#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_fragment_program.h"
#include "paths/arbfp/arb_key.h"
#include "paths/arbfp/arb_vertex_program.h"

namespace lt::arbfp {

namespace {

ArbPrograms generate_with(const Scene& scene, const Material& material, const PowVariant& variant,
                          bool translucency_term, const Layout& layout, const LightNumbers& numbers,
                          const GuardNeeds& guards) {
  const Key k = make_key(scene, material, variant, translucency_term, layout, numbers, guards);
  ArbPrograms out;
  out.notes = k.notes;
  out.fragment_program = fragment_program(k, material, out.lut, out.notes);
  out.vertex_program = vertex_program(k, out.notes);
  return out;
}

// The layouts worth trying for `lights` lights: by kind only when both kinds are there; a packing
// threshold only where it changes which groups are packed (every group but the last has four
// lights: 5 packs none, 4 the full groups, the last group's size all of them); dot sums only
// where a packed group has three or four lights. The scale fold saves one instruction per group
// wherever it applies, so it is always on.
std::vector<Layout> candidate_layouts(const Scene& scene) {
  bool point = false, directional = false;
  for (const Light& l : scene.lights) (l.type == Light::Type::Point ? point : directional) = true;
  const size_t n = scene.lights.size();
  const size_t last = n == 0 ? 0 : n - 4 * (group_count(n) - 1);
  std::vector<size_t> thresholds = {5};
  if (n >= 4) thresholds.push_back(4);
  if (last >= 2 && last < 4) thresholds.push_back(last);
  std::vector<Layout> out;
  for (bool by_kind : {false, true}) {
    if (by_kind && !(point && directional)) continue;
    for (size_t pack_min : thresholds) {
      out.push_back({by_kind, pack_min, false, true});
      if (pack_min <= 4 && (n >= 4 || last >= 3)) out.push_back({by_kind, pack_min, true, true});
    }
  }
  // The view dots apply to directional lights computed one by one, or to every light packed
  // (apply_layout decides which, or neither).
  const size_t layouts = out.size();
  for (size_t i = 0; i < layouts; ++i) {
    Layout l = out[i];
    l.view_dots = true;
    out.push_back(l);
  }
  return out;
}

// The programs of the layout with the shortest fragment program (ALU + TEX, then temporaries;
// the first of equals, so a scene packing does not shorten keeps the light-by-light program).
// Chosen on the program with the term and only the guards the scene needs, so `:guards=all`
// lays the lights out the same way and renders the same bits wherever no guard triggers
// (arb_guards_test), and the program without the term is the same program minus the term (the
// budget's term cost).
ArbPrograms generate_best(const Scene& scene, const Material& material, const PowVariant& variant,
                          const MaterialSurfaces& surfaces, bool translucency_term,
                          const LightNumbers& numbers) {
  PowVariant chooser = variant;
  chooser.all_guards = false;
  // Once, not once a layout (the layouts do not change what a guard can meet).
  const GuardNeeds needed = guard_needs(scene, surfaces, false, numbers);
  std::optional<ArbPrograms> best;
  Layout best_layout;
  std::pair<int, int> least;
  for (const Layout& l : candidate_layouts(scene)) {
    ArbPrograms p = generate_with(scene, material, chooser, true, l, numbers, needed);
    const budget::ProgramCounts c = ir::count(p.fragment_program);
    const std::pair<int, int> key(c.alu + c.tex, c.temporaries);
    if (best && !(key < least)) continue;
    best = std::move(p);
    best_layout = l;
    least = key;
  }
  if (variant.all_guards || !translucency_term) {
    return generate_with(scene, material, variant, translucency_term, best_layout, numbers,
                         variant.all_guards ? guard_needs(scene, surfaces, true, numbers) : needed);
  }
  return std::move(*best);
}

}  // namespace

ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         bool translucency_term, const LightNumbers& numbers) {
  return generate_arb(scene, material, variant, material_surfaces(scene, material),
                      translucency_term, numbers);
}

ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         const MaterialSurfaces& surfaces, bool translucency_term,
                         const LightNumbers& numbers) {
  ArbPrograms out = generate_best(scene, material, variant, surfaces, translucency_term, numbers);
  out.vertex = ir::print(out.vertex_program);
  out.fragment = ir::print(out.fragment_program);
  return out;
}

}  // namespace lt::arbfp