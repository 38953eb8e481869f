// t of directional lights from dot products the vertex program interpolates (issue 10's per-light
// goal). The eye is the origin of camera-relative space, so V = -P / |P| and
//   t = saturate(dot(V, -H)) = saturate((P.L + d (P.N)) / |P|),   H = L + N d.
// For a directional light L is constant, so d P and P.L are linear in the position: the vertex
// program writes (d P, P.L) to a texcoord and perspective-correct interpolation gives the same
// values at every pixel (up to float rounding). The fragment program then reads
//   DPH x, N, texcoord   (= d (N.P) + P.L)        MUL_SAT t, x, 1/|P|
// per light and 1/|P| (DP3, RSQ) once: 2 + 2 per light, where normalising V costs 3 and each
// light's H = L + N d and DP3_SAT another 2. With one directional light the term's t drops from
// 5 to 4 ALU, which is what brings the first light of a p = 8 material to 8 (arb_budget.h).
//
// Packed groups (arb_pack.h) use the same identity four lanes at a time, without V at all: the
// vertex program writes d P once and, per group, P.L (directional) or P.position (point) of
// each light in its lane; the fragment program computes 1/|P|, |P| and the addend
// c = d (N.P) / |P| once and then per group
//   directional:  t = saturate(P.L * 1/|P| + c)                                    (MAD_SAT)
//   point:        -(V.L) dist = (P.position - P.P) / |P| = P.position * 1/|P| - |P|  (MAD)
//                 t = saturate(that * 1/dist + c)                                  (MAD_SAT)
// where normalising V, d (N.V) and V.L per group took 3 + 2 shared and 4 per group.
//
// A single point light has no cheaper form: P.L = (P.position - P.P) / dist is not linear in P.
// The lower bound for its t is in arb_budget.h's comment on the term cost.
#pragma once

#include <string>
#include <vector>

#include "arb/arb_ir.h"

namespace lt::arbfp {

// The texcoords the fragment-lobe programs leave free: 0 is P, 1 the normal, 2 the thickness;
// 3..7 carry the view dots (and the per-light s * T of a vertex thickness, arb_generator.cpp).
inline constexpr int kFirstFreeTexcoord = 3;
inline constexpr int kFreeTexcoords = 8 - kFirstFreeTexcoord;

// Vertex program: out.xyz = d * P, out.w = P.L (L: the light's PARAM -direction).
void emit_view_dot_varying(ir::Block& code, const ir::Reg& out, const ir::Reg& P,
                           const ir::Reg& distortion, const ir::Reg& light_vector);

// Fragment program: dst (one component, as a source: V.swz("w")) = 1 / |P|. No pixel is at the eye
// (near > 0).
void emit_inverse_eye_distance(ir::Block& code, const ir::Reg& P, const ir::Reg& dst);

// Fragment program: t = saturate((d (N.P) + P.L) / |P|) into `t` (one component as a
// source, read_lane), from the
// interpolated (d P, P.L). N = 0 (no normal) leaves t = saturate(P.L / |P|) = saturate(-V.L),
// the model's H = L.
void emit_view_dot_t(ir::Block& code, const ir::Reg& N, const ir::Reg& varying,
                     const ir::Reg& inverse_eye_distance, const ir::Reg& t);

// Vertex program, packed groups: out.xyz = d * P (one texcoord for every group).
void emit_distorted_position(ir::Block& code, const ir::Reg& out, const ir::Reg& P,
                             const ir::Reg& distortion);
// Vertex program, packed groups: lane i of `out` = P . light_vectors[i] (-direction, or the
// camera-relative position).
void emit_group_view_dots(ir::Block& code, const ir::Reg& out, const ir::Reg& P,
                          const std::vector<ir::Reg>& light_vectors);
// Fragment program, packed groups: eye.x = P.P, eye.y = 1/|P|, eye.z = |P| (with
// `eye_distance`, which only point groups read), and addend (one component, as a source) =
// d (N.P) / |P| from the interpolated d P.
void emit_eye_terms(ir::Block& code, const ir::Reg& P, const ir::Reg& N,
                    const ir::Reg& distorted_position, const ir::Reg& eye, const ir::Reg& addend,
                    bool eye_distance);
// Fragment program: a directional group's t in the lanes `mask` of tv, from its interpolated
// P.L (`varying`), the eye terms and the addend.
void emit_group_view_dot_t(ir::Block& code, const std::string& mask, const ir::Reg& varying,
                           const ir::Reg& eye, const ir::Reg& addend, const ir::Reg& tv);
// Fragment program: a point group's -(V.L) dist = P.position / |P| - |P| in the lanes `mask` of
// tv, from its interpolated P.position; t = saturate(tv / dist + addend) follows (arb_pack.cpp,
// after the distance-0 guard, which replaces these lanes by -(V.N) = (N.P) / |P|).
void emit_point_view_dot(ir::Block& code, const std::string& mask, const ir::Reg& varying,
                         const ir::Reg& eye, const ir::Reg& tv);

}  // namespace lt::arbfp
