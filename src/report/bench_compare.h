// `bench --compare OLD/report.json`: this run against an earlier one, row by row (scene, path,
// variant). A ratio counts as changed only when the two 95% intervals do not overlap, so the
// noise both runs measured is not reported as a regression: what a CI job needs to catch a
// slowdown.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/bench.h"

namespace lt {

// The rows of an earlier report.json that can be compared (those with a ratio interval).
struct EarlierBench {
  std::filesystem::path file;
  struct Row {
    std::string scene, path, variant;
    RatioEstimate ratio;
  };
  std::vector<Row> rows;
  std::size_t without_interval = 0;  // rows of reports older than the interval column
};

// Reads and checks it first, so a bad file fails before the bench runs (InputError naming the
// file and the key).
EarlierBench read_earlier_bench(const std::filesystem::path& report_json);

struct RatioChange {
  std::string scene, path, variant;
  RatioEstimate before, after;
  bool slower() const { return after.low > before.high; }
};

struct BenchComparison {
  std::vector<RatioChange> changed;  // intervals apart: slower or faster
  std::size_t unchanged = 0;         // intervals overlap
  std::size_t only_now = 0, only_before = 0;
  std::size_t slower() const;
};

BenchComparison compare_bench(const EarlierBench& before, const std::vector<BenchRow>& now);

// compare.md: the changed rows with both intervals, and the counts.
std::string comparison_markdown(const EarlierBench& before, const BenchComparison& c);

}  // namespace lt
