#include "paths/arbfp/arb_view_dots.h"

namespace lt::arbfp {

using ir::Op;
using ir::Reg;

void emit_view_dot_varying(ir::Block& code, const Reg& out, const Reg& P, const Reg& distortion,
                           const Reg& light_vector) {
  code.op(Op::MUL, out.masked("xyz"), {P, distortion});
  code.op(Op::DP3, out.masked("w"), {P, light_vector});
}

void emit_inverse_eye_distance(ir::Block& code, const Reg& P, const Reg& dst) {
  code.text("# 1/|P| = 1/|eye - P|: the directional lights' t reads (d P, P.L) interpolated.\n");
  code.op(Op::DP3, dst.as_destination(), {P, P});
  code.op(Op::RSQ, dst.as_destination(), {dst});
}

void emit_view_dot_t(ir::Block& code, const Reg& N, const Reg& varying,
                     const Reg& inverse_eye_distance, const Reg& t) {
  code.op(Op::DPH, t.as_destination(), {N, varying});
  code.op_sat(Op::MUL, t.as_destination(), {t, inverse_eye_distance});
}

void emit_distorted_position(ir::Block& code, const Reg& out, const Reg& P, const Reg& distortion) {
  code.op(Op::MUL, out.masked("xyz"), {P, distortion});
}

void emit_group_view_dots(ir::Block& code, const Reg& out, const Reg& P,
                          const std::vector<Reg>& light_vectors) {
  for (size_t i = 0; i < light_vectors.size(); ++i) {
    code.op(Op::DP3, out.masked(std::string(1, "xyzw"[i])), {P, light_vectors[i]});
  }
}

void emit_eye_terms(ir::Block& code, const Reg& P, const Reg& N, const Reg& distorted_position,
                    const Reg& eye, const Reg& addend, bool eye_distance) {
  code.text(
      "# 1/|P|, |P| and c = d (N.P) / |P| once; the groups' t read their interpolated dots.\n");
  code.op(Op::DP3, eye.masked("x"), {P, P});
  code.op(Op::RSQ, eye.masked("y"), {eye.swz("x")});
  if (eye_distance) code.op(Op::MUL, eye.masked("z"), {eye.swz("x"), eye.swz("y")});
  code.op(Op::DP3, addend.as_destination(), {N, distorted_position});
  code.op(Op::MUL, addend.as_destination(), {addend, eye.swz("y")});
}

void emit_group_view_dot_t(ir::Block& code, const std::string& mask, const Reg& varying,
                           const Reg& eye, const Reg& addend, const Reg& tv) {
  code.op_sat(Op::MAD, tv.masked(mask), {varying, eye.swz("y"), addend});
}

void emit_point_view_dot(ir::Block& code, const std::string& mask, const Reg& varying,
                         const Reg& eye, const Reg& tv) {
  code.op(Op::MAD, tv.masked(mask), {varying, eye.swz("y"), -eye.swz("z")});
}

}  // namespace lt::arbfp
