// The TEV's per-component arithmetic (gx-hardware.md §1.2-1.4): operand widths, the regular
// equation with its fields decoded once (regular_op, which the per-draw plan of tev_plan.h keeps),
// the compare stage. The interpreter of the register state (tev.cpp run_tev, the definition the
// tests check) computes with these functions; the pixel stage's plan computes the same steps in
// vector lanes (tev_plan_lanes.cpp, each named after its function here), and
// tests/gx_tev_plan_test.cpp holds the two together on every target.
#pragma once

#include <algorithm>

#include "gx/gx_types.h"

namespace lt::gx::tev_arith {

// Register fields are narrow bit-fields; a value outside a field's width cannot reach the
// hardware, so every selector is read through its width [HWT gxtest/BPMemory.h L528-572].
constexpr u8 bits(u8 v, int width) {
  return static_cast<u8>(v & ((1 << width) - 1));
}

// d and the registers are 11-bit two's complement [HWT gxtest/BPMemory.h L1827-1849];
// GX_SetTevColorS10 masks with 0x7ff [OGC gx.c L3790-3803], so out-of-range values wrap.
constexpr s32 wrap11(s32 v) {
  return ((v & 0x7ff) ^ 0x400) - 0x400;
}

// a, b, c are 8-bit inputs: a register feeding them contributes its low 8 bits (wrap, not clamp)
// [DSW Tev.h InputRegType; HWT gxtest/tev.cpp L18-20].
constexpr s32 low8(s32 v) {
  return v & 255;
}

// The per-stage clamp: 0..255 with the clamp bit, else the 11-bit range [DSW Tev.cpp Tev::Draw
// Clamp255/Clamp1024; HWT gxtest/tev.cpp L31-34].
constexpr s32 stage_clamp(s32 r, bool clamp) {
  return clamp ? std::clamp(r, 0, 255) : std::clamp(r, -1024, 1023);
}

// A regular combiner's op, bias, scale and clamp fields decoded into the numbers its equation
// uses, so a caller that runs one stage for many pixels decodes them once.
struct RegularOp {
  bool sub = false;    // op bit: subtract
  int shift = 0;       // x2: 1, x4: 2, else 0
  int round = 128;     // the rounding term before >> 8
  bool halve = false;  // DIVIDE_2: an arithmetic shift right after the sum
  int bias = 0;        // +128, -128 or 0
  bool clamp = true;
};

inline RegularOp regular_op(u8 op, u8 bias, u8 scale, bool clamp) {
  RegularOp r;
  r.sub = bits(op, 1) == 1;
  const u8 sc = bits(scale, 2);
  // The scale is applied inside the lerp before the divide; DIVIDE_2 adds no rounding term, SUB
  // rounds with 127 [HWT gxtest/tev.cpp L24-26; DHW PixelShaderGen WriteTevRegular].
  r.shift = sc == 1 ? 1 : sc == 2 ? 2 : 0;
  r.round = sc == 3 ? 0 : r.sub ? 127 : 128;
  r.halve = sc == 3;
  // Bias 3 is the compare encoding and never reaches the regular equation from a stage; its LUT
  // entry is 0 [DSW Tev.h s_BiasLUT].
  const u8 bs = bits(bias, 2);
  r.bias = bs == 1 ? 128 : bs == 2 ? -128 : 0;
  r.clamp = clamp;
  return r;
}

// One component of a regular stage, the hardware-verified equation of gx-hardware.md §1.2 [HWT
// gxtest/tev.cpp L16-36]: a, b, c 0..255, d -1024..1023; the clamped result.
inline s32 apply_regular(const RegularOp& o, int a, int b, int c, int d) {
  // Step 1: c rescaled onto 0..256 so the lerp divides by 256 exactly (255 -> 256).
  const int c_prime = c + (c >> 7);
  // Step 2: the lerp, 0..65280.
  const int lerp = a * (256 - c_prime) + b * c_prime;
  // Steps 3-4: m >= 0, so >> 8 is a floor. The sign is applied after the shift (colour path of
  // DSW DrawColorRegular; §1.3 models alpha the same way).
  const int m = ((lerp << o.shift) + o.round) >> 8;
  // Step 5: d and the bias are scaled too.
  int r = ((d + o.bias) << o.shift) + (o.sub ? -m : m);
  // Step 6: DIVIDE_2 is an arithmetic shift, i.e. floor (-3 -> -2) [HWT L30].
  if (o.halve) r >>= 1;
  // Step 7.
  return stage_clamp(r, o.clamp);
}

// The four operands of one component as the combiner sees them: a, b, c 8 bits, d 11 bits.
struct Operands {
  s32 a, b, c, d;
};

inline Operands operands(s32 a, s32 b, s32 c, s32 d) {
  return {low8(a), low8(b), low8(c), wrap11(d)};
}

// The compare stage's condition: op bit 18 selects GT (0) or EQ (1) [HWT gxtest/BPMemory.h
// L538-545; OGC gx.c L3897-3904].
inline bool compare(u8 op, u32 a, u32 b) {
  return bits(op, 1) ? a == b : a > b;
}

// The R8 / GR16 / BGR24 comparands: red is the lowest byte [DSW Tev.cpp DrawColorCompare].
inline u32 packed(const Operands (&ops)[3], s32 Operands::*field, u8 mode) {
  u32 v = static_cast<u32>(ops[0].*field);
  if (mode >= 1) v |= static_cast<u32>(ops[1].*field) << 8;
  if (mode >= 2) v |= static_cast<u32>(ops[2].*field) << 16;
  return v;
}

// The condition of colour component i of a compare stage of mode `mode` (scale field); mode 3 is
// RGB8, each component compared on its own [DSW Tev.cpp DrawColorCompare].
inline bool color_condition(u8 op, u8 mode, const Operands (&col)[3], int i) {
  return mode == 3 ? compare(op, static_cast<u32>(col[i].a), static_cast<u32>(col[i].b))
                   : compare(op, packed(col, &Operands::a, mode), packed(col, &Operands::b, mode));
}

// The alpha compare's condition: mode 3 is A8; R8/GR16/BGR24 compare the *colour* combiner's a
// and b (HW-verified: [HWT gxtest/tev.cpp L178-232]; [DSW Tev.cpp DrawAlphaCompare]; PR#193).
inline bool alpha_condition(u8 op, u8 mode, const Operands (&col)[3], const Operands& alp) {
  return mode == 3 ? compare(op, static_cast<u32>(alp.a), static_cast<u32>(alp.b))
                   : compare(op, packed(col, &Operands::a, mode), packed(col, &Operands::b, mode));
}

// r = d + (cond ? c : 0), then the stage clamp: no bias, scale or rounding [DSW Tev.cpp
// DrawColorCompare / DrawAlphaCompare; OGC gx.c L3901-3904 writes bias 3 and the mode into the
// scale field].
inline s32 compare_result(const Operands& o, bool cond, bool clamp) {
  return stage_clamp(o.d + (cond ? o.c : 0), clamp);
}

}  // namespace lt::gx::tev_arith
