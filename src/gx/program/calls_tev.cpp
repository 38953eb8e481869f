// The TEV calls: stage order, colour and alpha combiners, registers, konst and swap tables.
#include "gx/program/machine.h"

namespace lt::gx::interp {

namespace {

TevStage& stage(Machine& m, size_t k) {
  return m.state.tev.stages[m.u(k)];
}

// GX_SetTevColorIn / GX_SetTevAlphaIn: the combiner's inputs a, b, c, d.
void set_inputs(TevCombiner& c, Machine& m) {
  c.a = m.u(1), c.b = m.u(2), c.c = m.u(3), c.d = m.u(4);
}

// GX_SetTevColorOp / GX_SetTevAlphaOp: a compare op (8..15) writes bias 3, scale bits
// (op >> 1) & 3 and op bit op & 1; bias and scale arguments are then ignored [OGC gx.c L3893].
void set_op(TevCombiner& c, Machine& m) {
  if (m.i(1) > 1 && m.i(1) < 8) m.fail_arg(1, "not a TEV operation");
  const long long op = m.i(1);
  if (op >= 8) {
    c.bias = 3;
    c.scale = static_cast<u8>((op >> 1) & 3);
    c.op = static_cast<u8>(op & 1);
  } else {
    if (m.i(2) == 3) m.fail_arg(2, "bias 3 selects a compare stage: pass a GX_TEV_COMP_* op");
    c.bias = m.u(2);
    c.scale = m.u(3);
    c.op = static_cast<u8>(op);
  }
  c.clamp = m.b(4);
  c.dest = m.u(5);
}

// libogc's GX_SetTevOp presets [OGC gx.c L3835-3869]: stage 0 reads the rasterised colour,
// later stages the previous stage's result.
void tev_preset(Machine& m) {
  TevStage& s = stage(m, 0);
  const bool first = m.i(0) == 0;
  const u8 c = first ? 10 : 0, a = first ? 5 : 0;  // RASC / CPREV, RASA / APREV
  constexpr u8 kZero = 15, kTexC = 8, kTexA = 9, kOne = 12, aZero = 7, aTexA = 4, aRasA = 5;
  switch (m.i(1)) {
    case 0:  // MODULATE
      s.color = {kZero, kTexC, c, kZero};
      s.alpha = {aZero, aTexA, a, aZero};
      break;
    case 1:  // DECAL
      s.color = {c, kTexC, kTexA, kZero};
      s.alpha = {aZero, aZero, aZero, a};
      break;
    case 2:  // BLEND
      s.color = {c, kOne, kTexC, kZero};
      s.alpha = {aZero, aTexA, a, aRasA};
      break;
    case 3:  // REPLACE
      s.color = {kZero, kZero, kZero, kTexC};
      s.alpha = {aZero, aZero, aZero, aTexA};
      break;
    default:  // PASSCLR
      s.color = {kZero, kZero, kZero, c};
      s.alpha = {aZero, aZero, aZero, a};
      break;
  }
  for (TevCombiner* comb : {&s.color, &s.alpha}) {
    comb->bias = 0;
    comb->op = 0;
    comb->scale = 0;
    comb->clamp = true;
    comb->dest = 0;
  }
}

}  // namespace

void add_tev_calls(CallTable& table) {
  using K = ParamKind;
  using G = NameGroup;
  const Param stage_p = integer(G::TevStage, 0, 15);
  const Param color_in = integer(G::ColorArg, 0, 15), alpha_in = integer(G::AlphaArg, 0, 7);
  const std::vector<Param> op_params = {stage_p,
                                        integer(G::TevOp, 0, 15),
                                        integer(G::TevBias, 0, 3),
                                        integer(G::TevScale, 0, 3),
                                        integer(G::Bool, 0, 1),
                                        integer(G::TevReg, 0, 3)};
  table.insert({
      // --- TEV [OGC gx.h L2559-3227] ---
      {"GX_SetNumTevStages",
       {{integer(G::Number, 1, 255)}, [](Machine& m) { m.state.tev.num_stages = m.u(0); }}},
      {"GX_SetTevOrder",
       {{stage_p, integer(G::TexCoord, 0, 255), integer(G::TexMap, 0, 0x1ff),
         integer(G::Channel, 0, 255)},
        [](Machine& m) {
          TevStage& s = stage(m, 0);
          const long long tc = m.i(1), map = m.i(2), ch = m.i(3);
          if (tc > 7 && tc != 0xff) m.fail_arg(1, "not a texture coordinate");
          if ((map & 0xff) > 7 && (map & 0xff) != 0xff) m.fail_arg(2, "not a texture map");
          s.texcoord = static_cast<u8>(tc);
          // GX_TEXMAP_NULL or the GX_TEXMAP_DISABLE bit turn the fetch off [OGC gx.c
          // GX_SetTevOrder].
          s.texmap = (map == 0xff || (map & 0x100)) ? kTexMapNull : static_cast<u8>(map);
          // The colour id: COLOR0 / ALPHA0 / COLOR0A0 rasterise channel 0, the *1 channel 1,
          // COLORZERO and COLORNULL read zero [OGC gx.c L100 _gxtevcolid].
          if (ch == 7 || ch == 8) m.fail_arg(3, "bump alpha is not modelled");
          if (ch > 8 && ch != 0xff) m.fail_arg(3, "not a colour channel");
          s.channel = ch == 6 || ch == 0xff ? static_cast<u8>(ch) : channel_index(ch) ? 5 : 4;
        }}},
      {"GX_SetTevColorIn",
       {{stage_p, color_in, color_in, color_in, color_in},
        [](Machine& m) { set_inputs(stage(m, 0).color, m); }}},
      {"GX_SetTevAlphaIn",
       {{stage_p, alpha_in, alpha_in, alpha_in, alpha_in},
        [](Machine& m) { set_inputs(stage(m, 0).alpha, m); }}},
      {"GX_SetTevColorOp", {op_params, [](Machine& m) { set_op(stage(m, 0).color, m); }}},
      {"GX_SetTevAlphaOp", {op_params, [](Machine& m) { set_op(stage(m, 0).alpha, m); }}},
      // GX_SetTevColor writes 0..255 into the 11-bit register fields [OGC gx.c L3775-3788].
      {"GX_SetTevColor",
       {{integer(G::TevReg, 0, 3), of(K::Color)},
        [](Machine& m) {
          const Color8 c = m.color(1);
          m.state.tev.registers[m.u(0)] = {c.r, c.g, c.b, c.a};
        }}},
      {"GX_SetTevColorS10",
       {{integer(G::TevReg, 0, 3), of(K::ColorS10)},
        [](Machine& m) { m.state.tev.registers[m.u(0)] = m.color_s10(1); }}},
      {"GX_SetTevKColor",
       {{integer(G::KColor, 0, 3), of(K::Color)},
        [](Machine& m) { m.state.tev.konst[m.u(0)] = m.color(1); }}},
      {"GX_SetTevKColorSel",
       {{stage_p, integer(G::KColorSel, 0, 31)},
        [](Machine& m) { stage(m, 0).konst_color_sel = m.u(1); }}},
      {"GX_SetTevKAlphaSel",
       {{stage_p, integer(G::KAlphaSel, 0, 31)},
        [](Machine& m) { stage(m, 0).konst_alpha_sel = m.u(1); }}},
      {"GX_SetTevOp", {{stage_p, integer(G::TevMode, 0, 4)}, tev_preset}},
      {"GX_SetTevSwapMode",
       {{stage_p, integer(G::Swap, 0, 3), integer(G::Swap, 0, 3)},
        [](Machine& m) {
          stage(m, 0).ras_swap = m.u(1);
          stage(m, 0).tex_swap = m.u(2);
        }}},
      {"GX_SetTevSwapModeTable",
       {{integer(G::Swap, 0, 3), integer(G::ColorComponent, 0, 3), integer(G::ColorComponent, 0, 3),
         integer(G::ColorComponent, 0, 3), integer(G::ColorComponent, 0, 3)},
        [](Machine& m) {
          m.state.tev.swap_tables[m.u(0)] = {m.u(1), m.u(2), m.u(3), m.u(4)};
        }}},
      // Indirect texturing is never enabled in this emulator, so "direct" is the state it
      // already models: the call is accepted because exported code sets it explicitly.
      {"GX_SetTevDirect", {{stage_p}, [](Machine&) {}}},
  });
}

}  // namespace lt::gx::interp
