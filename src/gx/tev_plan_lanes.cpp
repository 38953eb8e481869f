// TevPlan::run in 32-bit integer vector lanes, a pixel a lane. Compiled once per Highway target
// (hwy/foreach_target.h re-includes this file), outside the unity build (CMakeLists.txt). Each
// step names the scalar function of tev_arith.h it computes; every value fits 32 bits with room
// (the largest, a lerp shifted by x4, is 65280 * 4), so the lanes compute the scalar's integers
// exactly and the order of operations is free.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "gx/tev_plan_lanes.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/highway.h>

#include "gx/tev_plan.h"

HWY_BEFORE_NAMESPACE();
namespace lt::gx::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

using D = hn::ScalableTag<int32_t>;
using V = hn::Vec<D>;
using M = hn::Mask<D>;

V k(s32 x) {
  return hn::Set(D(), x);
}

// tev_arith::wrap11: ((v & 0x7ff) ^ 0x400) - 0x400.
V wrap11(V v) {
  return hn::Sub(hn::Xor(hn::And(v, k(0x7ff)), k(0x400)), k(0x400));
}

// tev_arith::stage_clamp.
V stage_clamp(V r, bool clamp) {
  return clamp ? hn::Min(hn::Max(r, k(0)), k(255)) : hn::Min(hn::Max(r, k(-1024)), k(1023));
}

// tev_arith::Operands: a, b, c their low 8 bits, d wrapped to 11.
struct Operands {
  V a, b, c, d;
};

Operands operands(const TevPlan::Values& values, u8 a, u8 b, u8 c, u8 d, size_t lane) {
  const D di;
  return {hn::And(hn::Load(di, values.v[a] + lane), k(255)),
          hn::And(hn::Load(di, values.v[b] + lane), k(255)),
          hn::And(hn::Load(di, values.v[c] + lane), k(255)),
          wrap11(hn::Load(di, values.v[d] + lane))};
}

// tev_arith::apply_regular, step by step.
V apply_regular(const tev_arith::RegularOp& o, const Operands& x) {
  const V c_prime = hn::Add(x.c, hn::ShiftRight<7>(x.c));
  const V lerp = hn::Add(hn::Mul(x.a, hn::Sub(k(256), c_prime)), hn::Mul(x.b, c_prime));
  // lerp >= 0, so the arithmetic shift is the scalar's floor.
  const V m = hn::ShiftRight<8>(hn::Add(hn::ShiftLeftSame(lerp, o.shift), k(o.round)));
  const V scaled_d = hn::ShiftLeftSame(hn::Add(x.d, k(o.bias)), o.shift);
  V r = o.sub ? hn::Sub(scaled_d, m) : hn::Add(scaled_d, m);
  if (o.halve) r = hn::ShiftRight<1>(r);  // arithmetic: the scalar's floor of a negative sum
  return stage_clamp(r, o.clamp);
}

// tev_arith::compare. The scalar compares as u32; the comparands are at most 24 bits (three
// 8-bit operands packed), so the signed lanes order them alike.
M compare(u8 op, V a, V b) {
  return tev_arith::bits(op, 1) ? hn::Eq(a, b) : hn::Gt(a, b);
}

// tev_arith::packed: red in the lowest byte.
V packed(const Operands (&ops)[3], V Operands::*field, u8 mode) {
  V v = ops[0].*field;
  if (mode >= 1) v = hn::Or(v, hn::ShiftLeft<8>(ops[1].*field));
  if (mode >= 2) v = hn::Or(v, hn::ShiftLeft<16>(ops[2].*field));
  return v;
}

// tev_arith::color_condition and alpha_condition: mode 3 compares the component's own operands;
// the others the colour combiner's packed a and b.
M packed_condition(u8 op, u8 mode, const Operands (&col)[3]) {
  return compare(op, packed(col, &Operands::a, mode), packed(col, &Operands::b, mode));
}

// tev_arith::compare_result.
V compare_result(const Operands& o, M cond, bool clamp) {
  return stage_clamp(hn::Add(o.d, hn::IfThenElseZero(cond, o.c)), clamp);
}

void RunPlan(const TevPlan& plan, TevPlan::Values& values, TevPlan::Output& out) {
  const D di;
  for (size_t lane = 0; lane < static_cast<size_t>(kPixelLanes); lane += hn::Lanes(di)) {
    for (int r = 0; r < 4 * kTevRegisters; ++r)
      hn::Store(k(plan.initial_register(r)), di, values.v[TevPlan::kRegisters + r] + lane);
    for (int n = 0; n < plan.num_stages(); ++n) {
      const TevPlan::Combiner& cc = plan.stage(n).color;
      const TevPlan::Combiner& ac = plan.stage(n).alpha;
      // Both combiners read before either writes (tev.cpp run_tev).
      Operands col[3];
      for (size_t i = 0; i < 3; ++i)
        col[i] = operands(values, cc.a[i], cc.b[i], cc.c[i], cc.d[i], lane);
      const Operands alp = operands(values, ac.a[0], ac.b[0], ac.c[0], ac.d[0], lane);

      V rgb[3];
      if (!cc.compare) {
        for (size_t i = 0; i < 3; ++i) rgb[i] = apply_regular(cc.regular, col[i]);
      } else if (cc.mode == 3) {
        for (size_t i = 0; i < 3; ++i)
          rgb[i] = compare_result(col[i], compare(cc.op, col[i].a, col[i].b), cc.clamp);
      } else {
        const M cond = packed_condition(cc.op, cc.mode, col);
        for (size_t i = 0; i < 3; ++i) rgb[i] = compare_result(col[i], cond, cc.clamp);
      }
      V alpha;
      if (!ac.compare)
        alpha = apply_regular(ac.regular, alp);
      else if (ac.mode == 3)
        alpha = compare_result(alp, compare(ac.op, alp.a, alp.b), ac.clamp);
      else
        alpha = compare_result(alp, packed_condition(ac.op, ac.mode, col), ac.clamp);

      for (int i = 0; i < 3; ++i)
        hn::Store(rgb[i], di, values.v[TevPlan::kRegisters + 4 * cc.dest + i] + lane);
      hn::Store(alpha, di, values.v[TevPlan::kRegisters + 4 * ac.dest + 3] + lane);
    }
    for (int i = 0; i < 3; ++i)
      hn::Store(hn::Load(di, values.v[TevPlan::kRegisters + 4 * plan.out_color() + i] + lane), di,
                out.c[i] + lane);
    hn::Store(hn::Load(di, values.v[TevPlan::kRegisters + 4 * plan.out_alpha() + 3] + lane), di,
              out.c[3] + lane);
  }
}

}  // namespace lt::gx::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace lt::gx {

HWY_EXPORT(RunPlan);

void TevPlan::run(Values& values, Output& out) const {
  HWY_DYNAMIC_DISPATCH(RunPlan)(*this, values, out);
}

}  // namespace lt::gx
#endif
