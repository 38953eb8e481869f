// The arbfp path's budget (`ltrender budget SCENE --path arbfp`): every program it generates for
// a scene, counted on its instruction list (arb_ir_counter.h) and checked against a profile pair
// (arb_profiles.h), plus the translucency term's own cost per light: the program with the term
// minus the same program without it, and the pass plan `render --profile` draws. It lives with
// the path (no other folder includes the ARB generator) and fills the one budget report
// (budget/report.h).
#pragma once

#include <string>
#include <vector>

#include "budget/arb_profiles.h"
#include "scene/scene.h"

namespace lt::budget {

// The term's cost in one material's fragment program. With D(k) = (the program for the scene's
// first k lights with the term) - (the same program, same layout, without it), entry k - 1 is
// D(k) - D(k - 1): what light k adds, the first including 1/|P| or V, which only the term needs.
// A further light's entry can jump where k lights choose another layout than k - 1 (the
// generator keeps the shortest whole program, whose term may cost more while the rest costs
// less: three packed point lights), so the goal for further lights (issue 10: <= 3) is read on
// the amortised figure (D(n) - D(1)) / (n - 1).
//
// Issue 10 asks <= 8 ALU for the first light with pow=mul for p <= 8. Directional lights meet
// it (arb_view_dots.h: 4 + chain + 1 = 8 at p = 8). A single point light at p = 8 takes 9, and
// no program can take fewer than 9, counted instruction by instruction on top of the program
// without the term (which has N, L = (position - P) / dist, 1/dist, att and the diffuse sum):
//  1. 1/|P|: t = saturate((P.L + d (P.N)) / |P|) needs |P|^2, which nothing in the base program
//     holds and no interpolant can (it is quadratic in P): one DP3; then one RSQ. >= 2.
//  2. The dot P.(L + N d) is a sum of six products of P with two different per-pixel registers
//     (L and N; an interpolant is linear in P, and P.L is not, L being (position - P) / dist).
//     One DP3/DP4/DPH pairs one register with one other: either L + N d is formed first (MAD)
//     and dotted with P, or P is dotted with each (two dots), or a DPH reads a register holding
//     P (or P/|P|) in xyz and d (P.N) in w, which takes an instruction to write (the texcoord
//     holding P is read-only) besides the DP3 of P.N. Either way >= 2. The factor 1/|P| then
//     needs a MUL of its own (MUL_SAT last, or P/|P| first): no instruction of step 2 can carry
//     it, its only other operands being registers without it. >= 1. So t >= 2 + 3 = 5.
//  3. t^8 by multiplies: each MUL or MAD at most doubles the degree in t, so 1 -> 8 takes >= 3.
//  4. The sum must gain (t^8 + a/s) s T, a product with the (rgb) s T, on top of the base
//     program's diffuse: the instruction of step 3 that reaches degree 8 is t^4 * t^4 (+ a/s),
//     a scalar; multiplying by s T and adding to the diffuse is one more MAD. >= 1.
// 5 + 3 + 1 = 9, which the generator emits (V: DP3 RSQ MUL; MAD H; DP3_SAT; 3 MUL/MAD; MAD).
// tests/arb_per_light_test.cpp holds every case to these counts.
struct TermCost {
  std::string material;
  struct Cost {
    int alu = 0, tex = 0;
  };
  std::vector<Cost> per_light;
  Cost total;
  // (total - first light) / (lights - 1) in ALU; 0 for one light.
  double further_light_alu() const;
};

// The term's cost for every material with translucency that some object uses, in scene order.
std::vector<TermCost> term_costs(const Scene& scene, const std::string& variant);

// Throws InputError for an unknown profile or variant. `profile` (empty: ps_2_0) may name
// either kind; its partner checks the other kind of program. Rows: each program (scope
// program), each pass of the plan (scope pass, no limits: the plan fits by construction), the
// term's cost and the pass bound per material (scope material, no limits).
Report run_budget(const Scene& scene, const std::string& variant, const std::string& profile);

}  // namespace lt::budget
