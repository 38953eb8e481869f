// The bench's interleaved timing (issue 11): the median's interval from order statistics, and
// the pairs, measuring time and warm-up it promises, on frame functions with known times.
#include "report/interleaved_timing.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lt {
namespace {

// Ranks from the binomial(n, 1/2) tables of a distribution-free median interval (e.g. Conover,
// Practical Nonparametric Statistics, table A3): 1-based (2, 9) for n = 10, (40, 61) for
// n = 100; too few samples for 95% give the whole range.
TEST(MedianInterval, RanksMatchTheBinomialTable) {
  EXPECT_EQ(median_interval_ranks(10), (std::pair<std::size_t, std::size_t>{1, 8}));
  EXPECT_EQ(median_interval_ranks(100), (std::pair<std::size_t, std::size_t>{39, 60}));
  EXPECT_EQ(median_interval_ranks(5), (std::pair<std::size_t, std::size_t>{0, 4}));
  EXPECT_EQ(median_interval_ranks(6), (std::pair<std::size_t, std::size_t>{0, 5}));
  // Coverage of the returned ranks is at least 95% and one rank narrower would be below it.
  for (std::size_t n : {8u, 20u, 37u, 250u}) {
    const auto [lo, hi] = median_interval_ranks(n);
    auto below = [n](std::size_t j) {  // P(X <= j - 1)
      double p = 0;
      for (std::size_t k = 0; k < j; ++k)
        p += std::exp(std::lgamma(n + 1.0) - std::lgamma(k + 1.0) - std::lgamma(n - k + 1.0) -
                      n * std::log(2.0));
      return p;
    };
    EXPECT_LE(2 * below(lo + 1), 0.05 + 1e-12) << n;
    EXPECT_GT(2 * below(lo + 2), 0.05) << n;
    EXPECT_EQ(hi, n - 1 - lo) << n;
  }
}

TEST(MedianInterval, EstimateOfKnownRatios) {
  const RatioEstimate e = estimate_ratio({1.9, 2.1, 2.0, 1.8, 2.2, 2.05, 1.95, 2.0, 2.0, 5.0});
  EXPECT_DOUBLE_EQ(e.median, 2.0);
  EXPECT_DOUBLE_EQ(e.low, 1.9);   // sorted sample 2 of 10
  EXPECT_DOUBLE_EQ(e.high, 2.2);  // sorted sample 9 of 10: the outlier 5.0 does not move it
  EXPECT_FALSE(e.wide());
  EXPECT_TRUE(estimate_ratio({1, 2, 1, 2, 1, 2, 1, 2, 1, 2}).wide());
}

TEST(Interleaved, PairsMeasuringTimeAndWarmUp) {
  // The path takes 3 ms and the baseline 1 ms, after five warm-up frames that get faster (a
  // JIT, caches): the settle test waits for three frames within 10% of their median.
  const double warming[] = {30, 20, 10, 5, 4};
  int path_calls = 0, baseline_calls = 0, timed_path = 0;
  auto path = [&](bool timed) {
    timed_path += timed;
    return ++path_calls <= 5 ? warming[path_calls - 1] : 3.0;
  };
  auto baseline = [&] { return ++baseline_calls <= 5 ? warming[baseline_calls - 1] / 3 : 1.0; };
  InterleaveOptions o;
  o.min_pairs = 10;
  o.min_seconds = 0.3;  // 100 frames of 3 ms
  o.min_warmup = 2;
  const InterleavedTiming t = time_interleaved(path, baseline, o);
  EXPECT_EQ(t.path_ms.size(), 100u);
  EXPECT_EQ(t.baseline_ms.size(), 300u);  // three 1 ms baseline frames fill each 3 ms path frame
  EXPECT_EQ(timed_path, 100);
  EXPECT_EQ(path_calls, 100 + 5 + 3);  // warm-up: five warming frames, then three that agree
  EXPECT_DOUBLE_EQ(t.ratio.median, 3.0);
  EXPECT_DOUBLE_EQ(t.ratio.low, 3.0);
  EXPECT_DOUBLE_EQ(t.ratio.high, 3.0);
  EXPECT_EQ(t.ratio.pairs, 100u);
}

// A machine with something else on it, as a virtual clock: every `period` ms of wall time a
// stall of `stall` ms lands on whichever frame is running. A path frame of 300 ms and baseline
// frames of 15 ms have the ratio 20 on an idle machine.
struct StalledMachine {
  double period, stall, now = 0, next_stall;
  StalledMachine(double period_ms, double stall_ms, double phase_ms)
      : period(period_ms), stall(stall_ms), next_stall(phase_ms) {}
  double frame(double work_ms) {
    double end = now + work_ms;
    while (next_stall < end) {  // each stall inside the frame delays its end
      end += stall;
      next_stall += period;
    }
    const double ms = end - now;
    now = end;
    return ms;
  }
};

double ratio_under_stalls(int max_baseline_frames, double phase) {
  StalledMachine m(/*period_ms=*/97, /*stall_ms=*/10, phase);  // ~10% of the machine taken
  InterleaveOptions o;
  o.min_pairs = 41;
  o.min_seconds = 0;
  o.max_baseline_frames_per_pair = max_baseline_frames;
  return time_interleaved([&](bool) { return m.frame(300); }, [&] { return m.frame(15); }, o)
      .ratio.median;
}

// The point of matched durations: a slow path's ratio does not rise with the background load.
// With one baseline frame a pair, the 300 ms frame takes three stalls and the 15 ms frame
// rarely one, so the ratio reads (300 + 30) / 15 = 22 instead of 20; with the baseline side as
// long as the path's, both sides take the same share and the ratio stays within 3% of 20.
TEST(Interleaved, MatchedDurationsKeepASlowPathsRatioUnderLoad) {
  for (double phase : {0.0, 13.0, 51.0, 88.0}) {
    EXPECT_NEAR(ratio_under_stalls(64, phase), 20.0, 0.6) << "phase " << phase;
    EXPECT_GT(ratio_under_stalls(1, phase), 21.5) << "phase " << phase;  // the old pairing
  }
}

// A machine where the baseline runs slow right after a heavy frame (on the machines here flat
// frames take up to twice their time for 20-30 ms after a 50-100 ms CPU frame): 60 ms path
// frames, 2 ms baseline frames, 4 ms for the five after a path frame. The steady ratio is 30.
InterleavedTiming time_with_slow_frames_after_the_path(int max_settling_frames) {
  int slow_left = 0;  // baseline frames still slowed by the last path frame
  auto path = [&](bool) {
    slow_left = 5;
    return 60.0;
  };
  auto baseline = [&] { return slow_left-- > 0 ? 4.0 : 2.0; };
  InterleaveOptions o;
  o.min_pairs = 20;
  o.min_seconds = 0;
  o.max_settling_frames = max_settling_frames;
  return time_interleaved(path, baseline, o);
}

// Timed, the slow frames would pull every other pair's baseline side up, and the median of two
// kinds of pair jumps between them from run to run; settled first, every pair reads the steady
// ratio.
TEST(Interleaved, BaselineSettlesAfterAPathFrameBeforeItIsTimed) {
  const InterleavedTiming t = time_with_slow_frames_after_the_path(16);
  EXPECT_DOUBLE_EQ(t.ratio.median, 30.0);
  EXPECT_DOUBLE_EQ(t.ratio.low, 30.0);
  EXPECT_DOUBLE_EQ(t.ratio.high, 30.0);
  for (double ms : t.baseline_ms) EXPECT_EQ(ms, 2.0);
  // The first pair follows the path's warm-up, and every odd pair's baseline its own path frame:
  // 1 + 10 blocks of five settling frames.
  EXPECT_EQ(t.settling_frames, 55u);
}

// Without settling, the same machine gives pairs of two kinds: the check that the test above
// can fail. A baseline block after a path frame averages five 4 ms frames into 25 frames.
TEST(Interleaved, UnsettledBaselineWouldReadTwoKindsOfPair) {
  const InterleavedTiming t = time_with_slow_frames_after_the_path(0);
  EXPECT_EQ(t.settling_frames, 0u);
  EXPECT_LT(t.ratio.low, 27.0);  // 60 / ((5 * 4 + 20 * 2) / 25) = 25
  EXPECT_DOUBLE_EQ(t.ratio.high, 30.0);
}

// Beyond the minimum, pairs go on until the interval is within the target, or the path has had
// its maximum time. The path's frames scatter +-10% (a fixed sequence), the baseline's do not.
TEST(Interleaved, PairsGoOnUntilTheIntervalIsNarrowOrTimeIsUp) {
  auto scattered_path = [] {
    return [k = 0](bool timed) mutable {
      if (!timed) return 10.0;  // a settled warm-up
      k = (k * 37 + 11) % 101;  // a fixed sequence in 0..100
      return 10.0 * (0.9 + 0.2 * k / 100.0);
    };
  };
  auto baseline = [] { return 1.0; };
  InterleaveOptions o;
  o.min_pairs = 10;
  o.min_seconds = 0;
  o.target_half_width = 0.02;
  o.max_seconds = 100;
  const InterleavedTiming narrow = time_interleaved(scattered_path(), baseline, o);
  EXPECT_GT(narrow.ratio.pairs, 10u);  // ten pairs of +-10% scatter give about +-6%
  EXPECT_LE(narrow.ratio.relative_half_width(), 0.02);
  // One pair fewer and the interval was still wider than the target (with 1 ms baseline
  // frames a pair's ratio is its path frame's milliseconds).
  const std::vector<double> fewer(narrow.path_ms.begin(), narrow.path_ms.end() - 1);
  EXPECT_GT(estimate_ratio(fewer).relative_half_width(), 0.02);

  o.max_seconds = 0.2;  // 20 frames of about 10 ms
  const InterleavedTiming capped = time_interleaved(scattered_path(), baseline, o);
  double seconds = 0;
  for (double ms : capped.path_ms) seconds += ms / 1000;
  EXPECT_GE(seconds, 0.2);
  EXPECT_LT(seconds - capped.path_ms.back() / 1000, 0.2);  // it stopped at the first pair over
  EXPECT_GT(capped.ratio.relative_half_width(), 0.02);
}

}  // namespace
}  // namespace lt
