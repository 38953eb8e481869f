// The fragment program's light loop four lights at a time (issue 10): for a group of up to four
// lights of one kind, the light vectors, N.L, V.L, t, the distance and the attenuation are
// computed in four-wide registers, one lane per light, from PARAMs that hold the lights
// transposed (one PARAM holds the x of four lights). Only the scalar opcodes (RSQ, RCP) still
// run once per light. The colour sums of such a group are dot products of its per-light scalars
// with the transposed colours (DP4, or DP3 for three lights).
#pragma once

#include <array>
#include <string>

#include "paths/arbfp/arb_emitters.h"

namespace lt::arbfp {

// Group g's lights transposed: x, y, z of each light's position (point) or L = -direction
// (directional) in lanes x..w, and a point group's attenuation coefficients kc, kl, kq.
struct PackedRows {
  ir::Reg x, y, z;
  ir::Reg kc, kl, kq;  // point groups only
};
PackedRows declare_packed_rows(ir::Block& decls, const LightList& lights, size_t group);
// The lights' colours transposed: red, green and blue of group g's lights; `scaled`: each
// times the light's translucency scale s.
std::array<ir::Reg, 3> declare_colour_rows(ir::Block& decls, const LightList& lights, size_t group,
                                           bool scaled);

// True when every light of group g is of one kind (the packed code has one form per kind).
bool group_has_one_kind(const LightList& lights, size_t group);

// What emit_packed_group writes and the scratch it may use; every register is written in the
// lanes `mask` only.
struct PackedGroup {
  std::string mask;  // the group's lanes ("xyz" for three lights)
  bool point = false;
  ir::Reg diffuse;  // out: saturate(N.L) per lane
  ir::Reg tv;       // out: t per lane; invalid when the fragment program computes no t
  ir::Reg att;      // out (point): the attenuation per lane
  ir::Reg dnv;      // in: d * (N.V), one component, read when tv is valid
  // in, when valid: t from the interpolated dots instead of V (arb_view_dots.h): the group's
  // texcoord, the eye terms (1/|P| in y, |P| in z) and the addend d (N.P) / |P|; dnv unused.
  ir::Reg view_dots, eye, view_addend;
  // Point groups' scratch: the light vectors' x, y, z, dist^2 (the group's lobe register, free
  // until the lobe is computed) and 1/dist (r, free after the normal).
  std::array<ir::Reg, 3> d;
  ir::Reg d2, inv;
  std::string distance_zero_lanes, floor_lanes;  // lanes whose guard the scene needs
  ir::Reg one;                                   // 1 in x (read by the distance-0 guard only)
};
void emit_packed_group(ir::Block& code, const Shading& s, const PackedRows& rows,
                       const PackedGroup& g);

}  // namespace lt::arbfp
