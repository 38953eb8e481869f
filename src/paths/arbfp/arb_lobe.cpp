#include "paths/arbfp/arb_lobe.h"

#include <cmath>

#include "model/pow_curves.h"

namespace lt::arbfp {

using ir::Op;
using ir::Reg;

namespace {

LobeLanes packed_lanes(const LobeInput& in) {
  LobeLanes out;
  for (size_t i = 0; i < in.lights; ++i) out.push_back(read_lane(in.lobe, i));
  return out;
}

Reg group_dst(const std::vector<Reg>& regs, size_t g, const LobeInput& in) {
  return regs[g].masked(group_mask(g, in.lights));
}

// exp2(n' * (t - 1)) = exp2(t * n' - n'): one MAD per group, one EX2 per light (EX2 is scalar).
LobeLanes lobe_exp2(LobeInput& in, double n) {
  const Reg sg = in.decls.param("sg", ir::vec4(n, 0, 0, 0), "n'");
  in.code.text("# " + in.variant.name() +
               ": t^p ~ exp2(n' * (t - 1)) = exp2(t * n' - n'). t <= 1, so EX2 never overflows.\n");
  for (size_t g = 0; g < in.tv.size(); ++g) {
    in.code.op(Op::MAD, group_dst(in.lobe, g, in), {in.tv[g], sg.swz("x"), -sg.swz("x")});
  }
  for (size_t i = 0; i < in.lights; ++i) {
    in.code.op(Op::EX2, write_lane(in.lobe, i), {read_lane(in.lobe, i)});
  }
  return packed_lanes(in);
}

// POW is EX2(p * LG2(t)) and LG2(0) = -inf: POW reads t clamped to the smallest normal float
// (finite everywhere), and the (t > 0) mask makes the model's 0 for t = 0 (0^p, p > 0; p = 0
// never gets here: flat lobe).
LobeLanes exact_vertex(LobeInput& in) {
  const Reg floor = in.decls.param("pow_floor", ir::vec4(std::ldexp(1.0, -126), 0, 0, 0), "2^-126");
  in.code.text("# non-integer p: POW of max(t, 2^-126), times (t > 0) for the model's 0^p = 0.\n");
  const Reg& r = in.s.r;
  for (size_t i = 0; i < in.lights; ++i) {
    in.code.op(Op::MAX, r.masked("x"), {read_lane(in.tv, i), floor.swz("x")});
    in.code.op(Op::POW, write_lane(in.lobe, i), {r.swz("x"), in.s.material.power});
  }
  for (size_t g = 0; g < in.tv.size(); ++g) {
    in.code.op(Op::SLT, r.masked(group_mask(g, in.lights)), {in.s.material.zero, in.tv[g]});
    in.code.op(Op::MUL, group_dst(in.lobe, g, in), {in.lobe[g], r});
  }
  return packed_lanes(in);
}

// Whether coords[i] is the last coordinate read from its temporary (a later TEX may then write
// the whole register: its other lanes are read already).
bool last_read_of_temporary(const std::vector<Reg>& coords, size_t i) {
  if (coords[i].file != ir::File::Temp) return false;
  for (size_t j = i + 1; j < coords.size(); ++j) {
    if (coords[j].same_register(coords[i])) return false;
  }
  return true;
}

// One TEX per light at coords[i], each writing a whole register of its own: Mesa's
// ARB_fragment_program (llvmpipe) returns wrong values from the third write-masked TEX into one
// register (measured: a packed lobe0.z was garbage). No ALU instruction comes between the TEXes,
// so after the first (which starts an indirection: its coordinate was computed) none adds one
// (ARB_fragment_program issue 24), whatever register it writes; the registers are, in order: the
// coordinate's own once this TEX is its last reader (a group's last light writes its t register),
// then `scratch` (registers dead by now), then new temporaries tex<i>.
std::vector<Reg> tex_per_light(ir::Block& code, const std::vector<Reg>& coords,
                               const std::vector<Reg>& scratch, const std::string& target) {
  std::vector<Reg> out;
  size_t next = 0;
  for (size_t i = 0; i < coords.size(); ++i) {
    Reg dst;
    if (last_read_of_temporary(coords, i)) {
      dst = coords[i].as_destination().masked("");
    } else if (next < scratch.size()) {
      dst = scratch[next++];
    } else {
      dst = code.program().temp("tex" + std::to_string(i));
    }
    code.tex(dst, coords[i], kLobeTableUnit, target);
    out.push_back(dst);
  }
  return out;
}

}  // namespace

LobeLanes lobe_exact(LobeInput& in) {
  in.code.text(
      "# pow=exact: POW is EX2(p * LG2(t)) and LG2(0) = -inf, so t = 0 is selected to the\n"
      "# model's 0 by CMP (-t < 0 only when t > 0); p = 0 never gets here (flat lobe).\n");
  for (size_t i = 0; i < in.lights; ++i) {
    in.code.op(Op::POW, write_lane(in.lobe, i), {read_lane(in.tv, i), in.s.material.power});
  }
  for (size_t g = 0; g < in.tv.size(); ++g) {
    in.code.op(Op::CMP, group_dst(in.lobe, g, in), {-in.tv[g], in.lobe[g], in.s.material.zero});
  }
  return packed_lanes(in);
}

LobeLanes lobe_lut(LobeInput& in, const model::PowerLut& lut) {
  in.decls.text("# texel-centre addressing (src/model/power_lut.h): u = t * (N-1)/N + 0.5/N\n");
  const Reg remap = in.decls.param(
      "lut", ir::vec4(lut.coordinate(1) - lut.coordinate(0), lut.coordinate(0), 0, 0));
  in.code.text("# " + in.variant.name() + ": t^p from a " + std::to_string(in.variant.lut_size) +
               "-texel 1D texture, linear filtering.\n");
  // The coordinate remaps of every group come before every TEX: a TEX reading a register an ALU
  // instruction wrote starts a new texture indirection (ARB_fragment_program issue 24), so this
  // order keeps the program at 2 indirections for any light count.
  for (size_t g = 0; g < in.tv.size(); ++g) {
    in.code.op(Op::MAD, group_dst(in.tv, g, in), {in.tv[g], remap.swz("x"), remap.swz("y")});
  }
  std::vector<Reg> coords;
  for (size_t i = 0; i < in.lights; ++i) coords.push_back(read_lane(in.tv, i));
  LobeLanes out;
  for (const Reg& r : tex_per_light(in.code, coords, in.scratch, "1D")) out.push_back(r.swz("x"));
  return out;
}

LobeLanes lobe_sg(LobeInput& in) {
  return lobe_exp2(in, model::sg_exponent(in.tr.power));
}

LobeLanes lobe_sg_simplified(LobeInput& in) {
  return lobe_exp2(in, in.tr.power);
}

LobeLanes lobe_sg_fitted(LobeInput& in) {
  const double p = in.tr.power, n = model::fit_sg_exponent(p);
  in.notes.push_back("pow=sg-fitted: n' = " + ir::num(n) + " for p = " + ir::num(p) +
                     " (sg: " + ir::num(model::sg_exponent(p)) + ")");
  return lobe_exp2(in, n);
}

// Both programs have MUL and MOV: the fragment program's pow=mul and the vertex program's
// pow=mul:vertex are the same code.
LobeLanes lobe_mul(LobeInput& in) {
  const unsigned long k = static_cast<unsigned long>(in.tr.power);
  const bool vertex = in.code.kind() == ir::ProgramKind::Vertex;
  in.code.text(std::string(vertex ? "# t^" : "# pow=mul: t^") + std::to_string(k) +
               " by repeated squaring (exact up to float rounding).\n");
  emit_mul_chain(in.code, k, in.tv, in.lobe, in.lights, in.addend);
  return packed_lanes(in);
}

LobeLanes lobe_mul_vertex(LobeInput& in, PowMethod method) {
  return method == PowMethod::Mul ? lobe_mul(in) : exact_vertex(in);
}

LobeLanes lobe_ramp(ir::Block& code, const std::vector<Reg>& t, const std::vector<Reg>& scratch) {
  code.text(
      "# Lobe ramp: the ramp's rgb at t replaces t^p, one TEX per light (texture[0], 2D, one\n"
      "# row: (t, t) reads what (t, 0.5) reads), after every light's ALU code.\n");
  return tex_per_light(code, t, scratch, "2D");
}

}  // namespace lt::arbfp
