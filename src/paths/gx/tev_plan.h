// The TEV state of one draw decoded once into what each stage reads and computes, so the pixel
// stage's per-pixel loop runs no selector switch, konst lookup or swizzle: every operand of every
// component is an index into one array of values (the pixel's registers, channel colours and
// texels, and the draw's constants), every combiner's fields are decoded numbers. run() returns
// exactly what run_tev (tev.h, the definition the tests check) returns for the same state and
// inputs; tests/gx_tev_plan_test.cpp holds the two together over random states and pixels.
#pragma once

#include <array>

#include "paths/gx/tev.h"
#include "paths/gx/tev_arith.h"

namespace lt::gx {

class TevPlan {
 public:
  // Where each value sits in a pixel's value array (TevValues). Registers, channels and texels
  // change per pixel; the constants and the konst values are the draw's.
  static constexpr int kRegisters = 0;                              // 4 registers x r g b a
  static constexpr int kChannels = kRegisters + 4 * kTevRegisters;  // COLOR0A0, COLOR1A1
  static constexpr int kTexels = kChannels + 4 * kMaxChannels;      // per stage, unswapped
  static constexpr int kZero = kTexels + 4 * kMaxTevStages;         // ZERO (and 8..11 konst)
  static constexpr int kHalf = kZero + 1;                           // HALF, 128
  static constexpr int kOne = kHalf + 1;                            // ONE, 255
  static constexpr int kKonst = kOne + 1;                           // per stage: KCSEL r g b, KASEL
  static constexpr int kValues = kKonst + 4 * kMaxTevStages;

  // One pixel's values; set up once with start() (the constants), then per pixel the channels
  // and the texels of the stages that fetch (run() resets the registers itself).
  struct Values {
    std::array<s32, kValues> v{};
    void set_channel(int channel, const Color8& c) { put(kChannels + 4 * channel, c); }
    void set_texel(int stage, const Color8& c) { put(kTexels + 4 * stage, c); }

   private:
    void put(int at, const Color8& c) {
      for (int i = 0; i < 4; ++i) v[static_cast<size_t>(at + i)] = c[i];
    }
  };

  explicit TevPlan(const TevState& state);

  // The constants of this draw written into `values` (once per worker and draw).
  void start(Values& values) const;
  // The TEV's output for the pixel whose inputs `values` holds; overwrites its registers.
  ColorS10 run(Values& values) const;

  int num_stages() const { return num_stages_; }

 private:
  // One combiner: the value index of each operand per component (the alpha combiner uses
  // component 0 only), and its fields decoded.
  struct Combiner {
    std::array<u8, 3> a{}, b{}, c{}, d{};
    bool compare = false;  // bias field 3
    tev_arith::RegularOp regular;
    u8 op = 0, mode = 0;  // compare: GT/EQ and R8/GR16/BGR24/RGB8 (A8)
    bool clamp = true;
    u8 dest = 0;  // register 0..3
  };
  struct Stage {
    Combiner color, alpha;
  };

  int num_stages_ = 1;
  std::array<Stage, kMaxTevStages> stages_{};
  std::array<s32, 4 * kTevRegisters> registers_{};  // the initial registers, wrapped to 11 bits
  std::array<s32, kValues - kZero> constants_{};    // ZERO, HALF, ONE, the konst values
  u8 out_color_ = 0, out_alpha_ = 0;                // the last stage's dest registers
};

}  // namespace lt::gx
