// Timing a path against the baseline so that the ratio repeats from run to run (issue 11):
// frames of the baseline and the path alternate in one context (A B A B ...), so a scheduler
// hiccup or a clock change hits both sides of a pair; the ratio is the median of the per-pair
// ratios, with a distribution-free 95% interval; every figure gets a minimum measuring time, not
// just a frame count; warm-up lasts until the frame time settles.
//
// Both sides of a pair last about as long: the baseline side is as many baseline frames as fill
// the path's frame. A 70 ms CPU frame paired with one 2 ms flat frame takes thirty times the
// share of whatever else runs on the machine (another process, a page-fault storm, a host's
// neighbour), so its ratio rises with the background load; with matched durations a
// disturbance is as likely to land on either side. (It does not make the CPU paths' ratios
// repeat from run to run: flat's own frame time drifts between runs, README "How far the ratios
// repeat".)
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
  int min_warmup = 2;        // frames before the settle test
  int max_warmup = 50;       // a path that never settles is timed anyway
  // The baseline side of a pair: frames until they add up to the path frame's time, at most
  // this many (a path 1000x slower than flat is then timed against 64 frames, not 1000).
  int max_baseline_frames_per_pair = 64;
};

struct InterleavedTiming {
  std::vector<double> path_ms;      // the timed path frames, in order (one a pair)
  std::vector<double> baseline_ms;  // every timed baseline frame, in order (one or more a pair)
  RatioEstimate ratio;              // of path frame / mean baseline frame, per pair
};

// `path_frame(timed)` and `baseline_frame()` each render one frame and return its milliseconds
// (bounded by glFinish); `timed` is false during the path's warm-up, so the caller takes the
// path's own figures from the timed frames only. Both warm up until three consecutive frames
// lie within 10% of their median. Each pair is one path frame and the baseline frames that
// fill its time (at least one), in alternating order.
InterleavedTiming time_interleaved(const std::function<double(bool timed)>& path_frame,
                                   const std::function<double()>& baseline_frame,
                                   const InterleaveOptions& options);

}  // namespace lt
