// Timing a path against the baseline so that the ratio repeats from run to run (issue 11):
// frames of the baseline and the path alternate in one context (A B A B ...), so a scheduler
// hiccup or a clock change hits both sides of a pair; the ratio is the median of the per-pair
// ratios, with a distribution-free 95% interval; warm-up lasts until the frame time settles.
//
// Both sides of a pair last about as long: the baseline side is as many baseline frames as fill
// the path's frame. A 70 ms CPU frame paired with one 2 ms flat frame takes thirty times the
// share of whatever else runs on the machine (another process, a page-fault storm, a host's
// neighbour), so its ratio rises with the background load; with matched durations a
// disturbance is as likely to land on either side.
//
// After a heavy frame the baseline runs slow for a while: on the 2-core machines here, flat
// frames right after a 50-100 ms CPU frame (half, gx) take up to twice their time for 20-30 ms
// (measured per frame, on both cores; the pairs alternated between a fast and a slow kind, and
// the median of such a mix jumps between them from run to run). Those frames are rendered
// but not timed: a baseline block that follows a path frame first runs untimed "settling"
// frames until one is within 10% of the baseline's level, as warm-up does for the first frame.
//
// Measuring time: at least `min_seconds` of the path and `min_pairs` pairs, then more pairs
// while the interval is wider than `target_half_width`, up to `max_seconds` of the path. A GL
// path's interval is narrow after half a second; a CPU path's pairs scatter more (its frame
// and flat's are different kinds of work and drift apart over seconds: over the 2.5 s windows
// of one 20 s measurement on both cores the ratio's standard deviation was 2.8-4.3%, over 5 s
// windows 2.4-3.5%).
#pragma once

#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace lt {

// The median of per-pair ratios and its interval.
struct RatioEstimate {
  double median = 0, low = 0, high = 0;  // low..high: >= 95% confidence for the median
  std::size_t pairs = 0;
  // Half the interval over the median: what the report calls the interval's width.
  double relative_half_width() const { return median > 0 ? (high - low) / 2 / median : 0; }
  // Rows whose interval is wider than +-10% are flagged in the report.
  bool wide() const { return relative_half_width() > 0.10; }
};

// 0-based ranks (j, k) of the sorted samples bounding a distribution-free interval of the median
// of n samples with coverage >= `confidence`: the binomial(n, 1/2) order-statistic interval
// (e.g. n = 10: samples 2 and 9 of 10, 1-based, covering 97.9%). With too few samples for that
// coverage (n < 6 at 95%) the whole range (0, n - 1) is returned.
std::pair<std::size_t, std::size_t> median_interval_ranks(std::size_t n, double confidence = 0.95);

RatioEstimate estimate_ratio(std::vector<double> ratios);

struct InterleaveOptions {
  int min_pairs = 10;        // metrics.md: at least 10 frames a figure
  double min_seconds = 0.5;  // measuring time of the path per figure (--min-time)
  // Beyond the minimum, pairs go on while the interval's half-width is above this fraction of
  // the median (--target-interval), up to max_seconds of the path (--max-time).
  double target_half_width = 0.02;
  double max_seconds = 2.5;
  int min_warmup = 2;   // frames before the settle test
  int max_warmup = 50;  // a path that never settles is timed anyway
  // The baseline side of a pair: frames until they add up to the path frame's time, at most
  // this many (a path 1000x slower than flat is then timed against 64 frames, not 1000).
  int max_baseline_frames_per_pair = 64;
  // Untimed baseline frames after a path frame, at most (a baseline that never settles back is
  // timed anyway).
  int max_settling_frames = 16;
  // Per-pair ratios of the same figure from earlier calls (the bench times a figure in rounds):
  // the target is judged on the interval of these and this call's pairs together; the minimums
  // and the maximum time count this call's alone.
  std::vector<double> earlier_ratios;
};

struct InterleavedTiming {
  std::vector<double> path_ms;      // the timed path frames, in order (one a pair)
  std::vector<double> baseline_ms;  // every timed baseline frame, in order (one or more a pair)
  std::vector<double> pair_ratios;  // path frame / mean baseline frame, one a pair, in order
  RatioEstimate ratio;              // of pair_ratios
  std::size_t settling_frames = 0;  // baseline frames rendered untimed after a path frame
};

// `path_frame(timed)` and `baseline_frame()` each render one frame and return its milliseconds
// (bounded by glFinish); `timed` is false during the path's warm-up, so the caller takes the
// path's own figures from the timed frames only. Both warm up until three consecutive frames
// lie within 10% of their median. Each pair is one path frame and the baseline frames that
// fill its time (at least one), in alternating order; a baseline block that follows a path frame
// starts once the baseline has settled back.
InterleavedTiming time_interleaved(const std::function<double(bool timed)>& path_frame,
                                   const std::function<double()>& baseline_frame,
                                   const InterleaveOptions& options);

}  // namespace lt
