// The TEV state decoded once per draw (tev_plan.h). The decoding mirrors run_tev's selectors
// (tev.cpp color_source, alpha_source, ras_color, the texel swizzle); the arithmetic, in lanes, is
// tev_plan_lanes.cpp, each step named after its scalar line in tev_arith.h.
#include "gx/tev_plan.h"

#include <algorithm>
#include <iterator>

namespace lt::gx {

namespace {

// Where one stage's operands come from, in value indices: its rasterised colour and its texel,
// each component after its swap table, and its konst values.
struct StageInputs {
  std::array<u8, 4> ras{}, tex{};
  u8 konst_rgb[3] = {}, konst_a = 0;
};

u8 index_of(int i) {
  return static_cast<u8>(i);
}

// A colour selector (GX_CC_*) for component i, as tev.cpp color_source reads it.
u8 color_value(u8 selector, int i, const StageInputs& in) {
  const u8 sel = tev_arith::bits(selector, 4);
  if (sel < 8) return index_of(TevPlan::kRegisters + 4 * (sel >> 1) + ((sel & 1) ? 3 : i));
  switch (static_cast<TevColorArg>(sel)) {
    case TevColorArg::TexC:
      return in.tex[static_cast<size_t>(i)];
    case TevColorArg::TexA:
      return in.tex[3];
    case TevColorArg::RasC:
      return in.ras[static_cast<size_t>(i)];
    case TevColorArg::RasA:
      return in.ras[3];
    case TevColorArg::One:
      return index_of(TevPlan::kOne);
    case TevColorArg::Half:
      return index_of(TevPlan::kHalf);
    case TevColorArg::Konst:
      return in.konst_rgb[i];
    default:
      return index_of(TevPlan::kZero);
  }
}

// An alpha selector (GX_CA_*), as tev.cpp alpha_source reads it.
u8 alpha_value(u8 selector, const StageInputs& in) {
  const u8 sel = tev_arith::bits(selector, 3);
  if (sel < 4) return index_of(TevPlan::kRegisters + 4 * sel + 3);
  switch (static_cast<TevAlphaArg>(sel)) {
    case TevAlphaArg::TexA:
      return in.tex[3];
    case TevAlphaArg::RasA:
      return in.ras[3];
    case TevAlphaArg::Konst:
      return in.konst_a;
    default:
      return index_of(TevPlan::kZero);
  }
}

// A swapped colour's components as value indices: component k reads component table[k] of the
// four values from `base` [DSW Tev.cpp Tev::Draw's swap of RasColor and TexColor].
std::array<u8, 4> swapped(int base, const std::array<u8, 4>& table) {
  std::array<u8, 4> out{};
  for (size_t k = 0; k < 4; ++k) out[k] = index_of(base + tev_arith::bits(table[k], 2));
  return out;
}

}  // namespace

TevPlan::TevPlan(const TevState& state) {
  num_stages_ = std::clamp(state.num_stages, 1, kMaxTevStages);
  for (int r = 0; r < kTevRegisters; ++r)
    for (int i = 0; i < 4; ++i)
      registers_[static_cast<size_t>(4 * r + i)] =
          tev_arith::wrap11(state.registers[static_cast<size_t>(r)][i]);
  constants_[kHalf - kZero] = 128;
  constants_[kOne - kZero] = 255;

  // TEXC/TEXA read the texel of the last stage that fetched, swapped by that stage's table, or 0
  // before any stage has (tev.cpp run_tev).
  std::array<u8, 4> tex{kZero, kZero, kZero, kZero};
  for (int n = 0; n < num_stages_; ++n) {
    const TevStage& stage = state.stages[static_cast<size_t>(n)];
    StageInputs in;
    if (stage.texmap != kTexMapNull)
      tex = swapped(kTexels + 4 * n, state.swap_tables[tev_arith::bits(stage.tex_swap, 2)]);
    in.tex = tex;
    // Channels 0..5 read COLOR0A0 or COLOR1A1 by their low bit, the rest read zero (tev.cpp
    // ras_color).
    if (stage.channel > 5)
      in.ras = {kZero, kZero, kZero, kZero};
    else
      in.ras = swapped(kChannels + 4 * (stage.channel & 1),
                       state.swap_tables[tev_arith::bits(stage.ras_swap, 2)]);
    const int konst = kKonst + 4 * n;
    for (int i = 0; i < 3; ++i) {
      constants_[static_cast<size_t>(konst + i - kZero)] =
          konst_value(stage.konst_color_sel, i, state.konst, false);
      in.konst_rgb[i] = index_of(konst + i);
    }
    constants_[static_cast<size_t>(konst + 3 - kZero)] =
        konst_value(stage.konst_alpha_sel, 3, state.konst, true);
    in.konst_a = index_of(konst + 3);

    Stage& out = stages_[static_cast<size_t>(n)];
    const auto decode = [](const TevCombiner& c, Combiner& o) {
      o.compare = tev_arith::bits(c.bias, 2) == 3;
      o.regular = tev_arith::regular_op(c.op, c.bias, c.scale, c.clamp);
      o.op = c.op;
      o.mode = tev_arith::bits(c.scale, 2);
      o.clamp = c.clamp;
      o.dest = tev_arith::bits(c.dest, 2);
    };
    decode(stage.color, out.color);
    decode(stage.alpha, out.alpha);
    for (size_t i = 0; i < 3; ++i) {
      const int comp = static_cast<int>(i);
      out.color.a[i] = color_value(stage.color.a, comp, in);
      out.color.b[i] = color_value(stage.color.b, comp, in);
      out.color.c[i] = color_value(stage.color.c, comp, in);
      out.color.d[i] = color_value(stage.color.d, comp, in);
    }
    out.alpha.a[0] = alpha_value(stage.alpha.a, in);
    out.alpha.b[0] = alpha_value(stage.alpha.b, in);
    out.alpha.c[0] = alpha_value(stage.alpha.c, in);
    out.alpha.d[0] = alpha_value(stage.alpha.d, in);
  }
  const TevStage& last = state.stages[static_cast<size_t>(num_stages_ - 1)];
  out_color_ = tev_arith::bits(last.color.dest, 2);
  out_alpha_ = tev_arith::bits(last.alpha.dest, 2);
}

void TevPlan::start(Values& values) const {
  for (int k = kZero; k < kValues; ++k)
    std::fill(std::begin(values.v[k]), std::end(values.v[k]),
              constants_[static_cast<size_t>(k - kZero)]);
}

}  // namespace lt::gx
