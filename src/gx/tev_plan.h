// The TEV state of one draw decoded once into what each stage reads and computes, so the pixel
// stage runs no selector switch, konst lookup or swizzle per pixel: every operand of every
// component is an index into one array of values (the pixel's registers, channel colours and
// texels, and the draw's constants), every combiner's fields are decoded numbers. run() evaluates
// kPixelLanes pixels at once, one a vector lane (tev_plan_lanes.cpp, Highway, the best target the
// CPU has), and returns for each exactly what run_tev (tev.h, the definition the tests check)
// returns for the same state and inputs; tests/gx_tev_plan_test.cpp holds the two together over
// random states and pixels on every target.
#pragma once

#include <array>

#include "gx/tev.h"
#include "gx/tev_arith.h"

namespace lt::gx {

class TevPlan {
 public:
  // Where each value sits in a pixel's value array (Values). Registers, channels and texels
  // change per pixel; the constants and the konst values are the draw's.
  static constexpr int kRegisters = 0;                              // 4 registers x r g b a
  static constexpr int kChannels = kRegisters + 4 * kTevRegisters;  // COLOR0A0, COLOR1A1
  static constexpr int kTexels = kChannels + 4 * kMaxChannels;      // per stage, unswapped
  static constexpr int kZero = kTexels + 4 * kMaxTevStages;         // ZERO (and 8..11 konst)
  static constexpr int kHalf = kZero + 1;                           // HALF, 128
  static constexpr int kOne = kHalf + 1;                            // ONE, 255
  static constexpr int kKonst = kOne + 1;                           // per stage: KCSEL r g b, KASEL
  static constexpr int kValues = kKonst + 4 * kMaxTevStages;

  // The values of kPixelLanes pixels, value by value (v[value][lane]: a value of every pixel is
  // one load); set up once with start() (the constants, in every lane), then per run the
  // channels and the texels of the stages that fetch (run() resets the registers itself).
  struct Values {
    alignas(64) s32 v[kValues][kPixelLanes] = {};
    // Component `component` of channel `channel`, a lane a pixel.
    s32* channel(int channel, int component) { return v[kChannels + 4 * channel + component]; }
    void set_texel(int stage, int lane, const Color8& c) {
      for (int i = 0; i < 4; ++i) v[kTexels + 4 * stage + i][lane] = c[i];
    }
  };
  // The TEV's output of each lane, component by component (r, g, b, a), -1024..1023.
  struct Output {
    alignas(64) s32 c[4][kPixelLanes] = {};
    ColorS10 at(int lane) const {
      return {static_cast<s16>(c[0][lane]), static_cast<s16>(c[1][lane]),
              static_cast<s16>(c[2][lane]), static_cast<s16>(c[3][lane])};
    }
  };

  explicit TevPlan(const TevState& state);

  // The constants of this draw written into every lane of `values` (once per band and draw).
  void start(Values& values) const;
  // The TEV's output for each lane's pixel, whose inputs `values` holds; overwrites its
  // registers. Every lane is run: a caller ignores the lanes that hold no pixel.
  void run(Values& values, Output& out) const;

  int num_stages() const { return num_stages_; }

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
  // What the lanes read (tev_plan_lanes.cpp).
  const Stage& stage(int n) const { return stages_[static_cast<size_t>(n)]; }
  s32 initial_register(int value) const { return registers_[static_cast<size_t>(value)]; }
  u8 out_color() const { return out_color_; }
  u8 out_alpha() const { return out_alpha_; }

 private:
  int num_stages_ = 1;
  std::array<Stage, kMaxTevStages> stages_{};
  std::array<s32, 4 * kTevRegisters> registers_{};  // the initial registers, wrapped to 11 bits
  std::array<s32, kValues - kZero> constants_{};    // ZERO, HALF, ONE, the konst values
  u8 out_color_ = 0, out_alpha_ = 0;                // the last stage's dest registers
};

}  // namespace lt::gx
