// The pixel stage's TEV plan (src/gx/tev_plan.h) against the interpreter it replaces in the
// per-pixel loop (tev.h run_tev, which tests/gx_tev_test.cpp holds to the hardware tests): over
// seeded random register states -- every colour and alpha selector, konst selector, swap table,
// channel, fetch pattern, regular and compare stage, scale, bias, clamp, destination, and fields
// wider than the hardware's -- and several pixels per state through one plan and one value array
// (as a worker reuses them), the two must agree bit for bit, a pixel a lane, on every vector
// target the machine runs.
#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>
#include <random>
#include <vector>

#include "gx/tev.h"
#include "gx/tev_plan.h"

namespace lt::gx {
namespace {

// Raw mt19937 output (fully specified by the standard), not a distribution (implementation
// defined), so the states are the same with every standard library.
struct PlanRng {
  std::mt19937 engine;
  int below(int n) { return static_cast<int>(engine() % static_cast<unsigned>(n)); }
  u8 byte_below(int n) { return static_cast<u8>(below(n)); }
  // A register field: in its range three times in four, else any byte (the narrow field then
  // keeps its low bits, which both evaluators must do alike).
  u8 field(int range) { return below(4) == 0 ? byte_below(256) : byte_below(range); }
  Color8 color() { return {byte_below(256), byte_below(256), byte_below(256), byte_below(256)}; }
};

TevCombiner plan_random_combiner(PlanRng& rng, int selectors) {
  TevCombiner t;
  t.a = rng.field(selectors);
  t.b = rng.field(selectors);
  t.c = rng.field(selectors);
  t.d = rng.field(selectors);
  t.bias = rng.field(4);  // 3 = compare
  t.op = rng.field(2);
  t.scale = rng.field(4);
  t.clamp = rng.below(2) == 1;
  t.dest = rng.field(4);
  return t;
}

TevState plan_random_state(PlanRng& rng) {
  TevState st;
  // 0 and 17 too: both evaluators clamp the count to 1..16.
  st.num_stages = rng.below(18);
  constexpr u8 kChannelIds[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, kColorNull};
  for (TevStage& sg : st.stages) {
    sg.texcoord = rng.below(9) == 8 ? kTexCoordNull : rng.byte_below(8);
    sg.texmap = rng.below(3) == 0 ? kTexMapNull : rng.byte_below(8);
    sg.channel = kChannelIds[rng.below(10)];
    sg.color = plan_random_combiner(rng, 16);
    sg.alpha = plan_random_combiner(rng, 8);
    sg.konst_color_sel = rng.field(32);
    sg.konst_alpha_sel = rng.field(32);
    sg.ras_swap = rng.field(4);
    sg.tex_swap = rng.field(4);
  }
  // Registers over the whole s16 range: beyond 11 bits they wrap (GX_SetTevColorS10's mask).
  for (ColorS10& r : st.registers)
    for (int k = 0; k < 4; ++k) r[k] = static_cast<s16>(rng.below(65536) - 32768);
  for (Color8& k : st.konst) k = rng.color();
  for (auto& table : st.swap_tables)
    for (u8& e : table) e = rng.field(4);
  return st;
}

std::string describe(const ColorS10& c) {
  return std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + "," +
         std::to_string(c.a);
}

TEST(GxTevPlan, MatchesRunTevOverRandomStatesAndPixels) {
  PlanRng rng{std::mt19937(20261206)};
  // What the random states reached, so a change to the generator that stops covering a case
  // fails here rather than passing on less.
  std::array<int, 16> color_selectors{};
  std::array<int, 8> alpha_selectors{};
  std::array<int, 32> konst_selectors{};
  std::array<int, 4> color_compare_modes{}, alpha_compare_modes{};
  int regular = 0, unclamped = 0, fetching = 0;

  const std::vector<std::int64_t> targets = hwy::SupportedAndGeneratedTargets();
  ASSERT_FALSE(targets.empty());
  for (int program = 0; program < 2000; ++program) {
    const TevState st = plan_random_state(rng);
    const TevPlan plan(st);
    TevPlan::Values values;
    plan.start(values);
    const int stages = std::clamp(st.num_stages, 1, kMaxTevStages);
    for (int n = 0; n < stages; ++n) {
      const TevStage& sg = st.stages[static_cast<size_t>(n)];
      for (u8 s : {sg.color.a, sg.color.b, sg.color.c, sg.color.d}) ++color_selectors[s & 15];
      for (u8 s : {sg.alpha.a, sg.alpha.b, sg.alpha.c, sg.alpha.d}) ++alpha_selectors[s & 7];
      ++konst_selectors[sg.konst_color_sel & 31];
      ++konst_selectors[sg.konst_alpha_sel & 31];
      if ((sg.color.bias & 3) == 3) ++color_compare_modes[sg.color.scale & 3];
      if ((sg.alpha.bias & 3) == 3) ++alpha_compare_modes[sg.alpha.scale & 3];
      regular += (sg.color.bias & 3) != 3;
      unclamped += !sg.color.clamp;
      fetching += sg.texmap != kTexMapNull;
    }
    // A pixel a lane. The pixel stage writes the channels and only the fetching stages'
    // texels; the other texels run_tev is given are noise it must ignore.
    std::array<TevPixelInputs, kPixelLanes> in;
    for (int lane = 0; lane < kPixelLanes; ++lane) {
      for (int c = 0; c < kMaxChannels; ++c) {
        const Color8 colour = rng.color();
        in[lane].channels[static_cast<size_t>(c)] = colour;
        for (int i = 0; i < 4; ++i) values.channel(c, i)[lane] = colour[i];
      }
      for (int n = 0; n < kMaxTevStages; ++n) {
        in[lane].texels[static_cast<size_t>(n)] = rng.color();
        if (st.stages[static_cast<size_t>(n)].texmap != kTexMapNull)
          values.set_texel(n, lane, in[lane].texels[static_cast<size_t>(n)]);
      }
    }
    // Every target on the same values, twice (a worker reuses its values: run() must reset what
    // it wrote), each lane against run_tev.
    for (std::int64_t target : targets) {
      hwy::SetSupportedTargetsForTest(target);
      for (int repeat = 0; repeat < 2; ++repeat) {
        TevPlan::Output out;
        plan.run(values, out);
        for (int lane = 0; lane < kPixelLanes; ++lane) {
          const ColorS10 want = run_tev(st, in[lane]);
          const ColorS10 got = out.at(lane);
          ASSERT_EQ(got, want) << hwy::TargetName(target) << " program " << program << " lane "
                               << lane << ": plan " << describe(got) << ", run_tev "
                               << describe(want);
        }
      }
    }
    hwy::SetSupportedTargetsForTest(0);
  }
  // Every target the machine runs was compared (the emulated one always is).
  EXPECT_GE(targets.size(), 2u);
  for (size_t s = 0; s < color_selectors.size(); ++s)
    EXPECT_GT(color_selectors[s], 100) << "colour selector " << s;
  for (size_t s = 0; s < alpha_selectors.size(); ++s)
    EXPECT_GT(alpha_selectors[s], 100) << "alpha selector " << s;
  for (size_t s = 0; s < konst_selectors.size(); ++s)
    EXPECT_GT(konst_selectors[s], 100) << "konst selector " << s;
  for (size_t m = 0; m < 4; ++m) {
    EXPECT_GT(color_compare_modes[m], 100) << "colour compare mode " << m;
    EXPECT_GT(alpha_compare_modes[m], 100) << "alpha compare mode " << m;
  }
  EXPECT_GT(regular, 1000);
  EXPECT_GT(unclamped, 1000);
  EXPECT_GT(fetching, 1000);
}

// The plan reads the state once: a state changed after the plan was made does not reach it (the
// pixel stage builds one plan per draw, from the draw's state), and a second plan of the changed
// state follows the change.
TEST(GxTevPlan, IsASnapshotOfItsState) {
  TevState st;
  st.stages[0].color.d = static_cast<u8>(TevColorArg::Konst);
  st.stages[0].alpha.d = static_cast<u8>(TevAlphaArg::Konst);
  st.stages[0].konst_color_sel = 0;  // 255
  st.stages[0].konst_alpha_sel = 4;  // 128
  const TevPlan before(st);
  st.stages[0].konst_color_sel = 7;  // 32
  const TevPlan after(st);
  TevPlan::Values a, b;
  before.start(a);
  after.start(b);
  TevPlan::Output out_a, out_b;
  before.run(a, out_a);
  after.run(b, out_b);
  EXPECT_EQ(out_a.at(0), (ColorS10{255, 255, 255, 128}));
  EXPECT_EQ(out_b.at(kPixelLanes - 1), (ColorS10{32, 32, 32, 128}));
}

}  // namespace
}  // namespace lt::gx
