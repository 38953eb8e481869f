// Timing a path against the baseline so that the ratio repeats from run to run (issue 11):
// frames of the baseline and the path alternate in one context (A B A B ...), so a scheduler
// hiccup or a clock change hits both sides of a pair; the ratio is the median of the per-pair
// ratios, with a distribution-free 95% interval; every figure gets a minimum measuring time, not
// just a frame count; warm-up lasts until the frame time settles.
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
};

struct InterleavedTiming {
  std::vector<double> path_ms, baseline_ms;  // the timed frames, in order
  RatioEstimate ratio;
};

// `path_frame(timed)` and `baseline_frame()` each render one frame and return its milliseconds
// (bounded by glFinish); `timed` is false during the path's warm-up, so the caller takes the
// path's own figures from the timed frames only. Both warm up until three consecutive frames
// lie within 10% of their median.
InterleavedTiming time_interleaved(const std::function<double(bool timed)>& path_frame,
                                   const std::function<double()>& baseline_frame,
                                   const InterleaveOptions& options);

}  // namespace lt
