#include "report/interleaved_timing.h"

#include <algorithm>
#include <cmath>

namespace lt {

namespace {

double median_of(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// Frames until the last three are within 10% of their median (JIT, thread start-up and caches
// are done), at least `min` and at most `max` of them. Returns the median of the last three:
// the level the frame time settled at.
double warm_up(const std::function<double()>& frame, int min, int max) {
  std::vector<double> recent;
  for (int i = 0; i < max; ++i) {
    recent.push_back(frame());
    if (static_cast<int>(recent.size()) < std::max(min, 3)) continue;
    const std::vector<double> last(recent.end() - 3, recent.end());
    const double m = median_of(last);
    const bool settled = std::all_of(last.begin(), last.end(),
                                     [m](double x) { return std::fabs(x - m) <= 0.10 * m; });
    if (settled) break;
  }
  if (recent.size() < 3) return recent.empty() ? 0 : recent.back();
  return median_of(std::vector<double>(recent.end() - 3, recent.end()));
}

}  // namespace

std::pair<std::size_t, std::size_t> median_interval_ranks(std::size_t n, double confidence) {
  if (n == 0) return {0, 0};
  // P(X <= j - 1) for X ~ binomial(n, 1/2), summed in log space (n may be thousands).
  const double tail = (1.0 - confidence) / 2.0;
  double cdf = 0;
  std::size_t j = 0;  // the largest j with P(X <= j - 1) <= tail, as a 0-based rank
  for (std::size_t k = 0; k < n; ++k) {
    const double log_p =
        std::lgamma(static_cast<double>(n) + 1) - std::lgamma(static_cast<double>(k) + 1) -
        std::lgamma(static_cast<double>(n - k) + 1) - static_cast<double>(n) * std::log(2.0);
    cdf += std::exp(log_p);
    if (cdf > tail) break;
    j = k + 1;
  }
  if (j == 0) return {0, n - 1};
  // 1-based samples j and n - j + 1 bound the interval: 0-based j - 1 and n - j.
  return {j - 1, n - j};
}

RatioEstimate estimate_ratio(std::vector<double> ratios) {
  RatioEstimate e;
  e.pairs = ratios.size();
  if (ratios.empty()) return e;
  std::sort(ratios.begin(), ratios.end());
  e.median = median_of(ratios);
  const auto [lo, hi] = median_interval_ranks(ratios.size());
  e.low = ratios[lo];
  e.high = ratios[hi];
  return e;
}

InterleavedTiming time_interleaved(const std::function<double(bool timed)>& path_frame,
                                   const std::function<double()>& baseline_frame,
                                   const InterleaveOptions& o) {
  const double warm_baseline_ms = warm_up(baseline_frame, o.min_warmup, o.max_warmup);
  const double warm_path_ms =
      warm_up([&] { return path_frame(false); }, o.min_warmup, o.max_warmup);
  InterleavedTiming t;
  std::vector<double> ratios;
  double path_seconds = 0;
  // The baseline's level: the median of its last timed frames (it drifts slowly over a row).
  auto baseline_level = [&] {
    constexpr std::size_t kRecent = 31;
    if (t.baseline_ms.empty()) return warm_baseline_ms;
    const std::size_t n = std::min(kRecent, t.baseline_ms.size());
    return median_of(std::vector<double>(t.baseline_ms.end() - n, t.baseline_ms.end()));
  };
  // The baseline frames whose total comes nearest `span` ms (at least one, at most the option's
  // cap: another frame is taken while it would end closer to `span` than stopping does); returns
  // their mean. After a path frame, untimed frames first until one is back within 10% of the
  // baseline's level; that one is the block's first.
  auto baseline_block = [&](double span, bool after_path) {
    double ms = baseline_frame();
    if (after_path) {
      const double level = baseline_level();
      for (int k = 0; k < o.max_settling_frames && ms > 1.10 * level; ++k) {
        ++t.settling_frames;
        ms = baseline_frame();
      }
    }
    double sum = 0;
    int n = 0;
    while (true) {
      t.baseline_ms.push_back(ms);
      sum += ms;
      ++n;
      if (sum + 0.5 * sum / n >= span || n >= o.max_baseline_frames_per_pair) break;
      ms = baseline_frame();
    }
    return sum / n;
  };
  const double max_seconds = std::max(o.max_seconds, o.min_seconds);
  auto more_pairs = [&] {
    if (static_cast<int>(ratios.size()) < o.min_pairs || path_seconds < o.min_seconds) return true;
    if (path_seconds >= max_seconds) return false;
    std::vector<double> all = o.earlier_ratios;
    all.insert(all.end(), ratios.begin(), ratios.end());
    return estimate_ratio(std::move(all)).relative_half_width() > o.target_half_width;
  };
  // The first pair's baseline side needs the path's duration before the path runs: the path's
  // warm-up level stands in until a timed frame exists.
  double last_path_ms = warm_path_ms;
  while (more_pairs()) {
    // The baseline first in even pairs and second in odd ones, so that neither side always
    // follows the other (a frame can pay for its predecessor's work still in flight). An even
    // pair's baseline follows the odd pair's baseline (or, in the first pair, the path's
    // warm-up); an odd pair's follows its own path frame.
    const bool baseline_first = ratios.size() % 2 == 0;
    double base = 0;
    if (baseline_first) base = baseline_block(last_path_ms, ratios.empty());
    const double path = path_frame(true);
    if (!baseline_first) base = baseline_block(path, true);
    last_path_ms = path;
    t.path_ms.push_back(path);
    ratios.push_back(base > 0 ? path / base : 0);
    path_seconds += path / 1000.0;
  }
  t.pair_ratios = ratios;
  t.ratio = estimate_ratio(std::move(ratios));
  return t;
}

}  // namespace lt
