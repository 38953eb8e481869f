// `ltrender bench`: every scene through every path and variant, speed against error, in one run
// (metrics.md): median and min of N frames after warm-up, each bounded by glFinish, at the
// scene's size and at 1280x720, with the `flat` baseline measured in the same session so the
// ratio path/flat is the technique's cost. A new path or variant adds rows by itself.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "load/load_scene.h"
#include "metrics/compare.h"
#include "paths/frame_stats.h"
#include "paths/path.h"
#include "report/console_bytes.h"
#include "report/frame_work.h"
#include "report/interleaved_timing.h"

namespace lt {

// How long the timing at 1280x720 goes on, by name: `precise` (the default, to the CI
// standard: BenchOptions' own values) or `quick` (bench --quick: one round and a short minimum,
// for a person comparing two variants). set_timing_mode is the one place a mode's values live.
enum class TimingMode { Precise, Quick };
const char* to_string(TimingMode mode);

// Which variants of each path get rows (bench --variants): every one, each path's default, or
// the default and the variants marked VariantRun::Story (./run.sh's quick run).
enum class VariantSelection { All, Defaults, Story };
// The names --variants takes (bench and sweep): "all", "default", "story".
const std::map<std::string, VariantSelection>& variant_selections();
bool selected(const PathInfo& path, const VariantInfo& variant, VariantSelection selection);

// A variant a path does not list, given to bench by name (`bench --add-variant PATH:VARIANT`):
// gx's stored vertex layouts, say, whose combinations no list can hold. Its rows are made as a
// listed variant's are.
struct AddedVariant {
  std::string path, variant;  // variant: canonical (PathInfo::parse_variant)
};
// "gx:t=vertex:vtx=s16/auto" -> {"gx", its canonical spelling}: the path's name ends at the
// first ':'. Throws InputError naming --add-variant and the text for an unknown path or a
// variant the path refuses.
AddedVariant parse_added_variant(const std::string& text);

struct BenchOptions {
  std::vector<std::filesystem::path> scenes;
  SceneOptions scene_options;      // --lights
  std::vector<std::string> paths;  // empty: every path
  VariantSelection variants = VariantSelection::All;
  std::vector<AddedVariant> added_variants;  // --add-variant: rows besides the selected ones
  std::filesystem::path out_dir;
  int frames = 10;  // >= 10 (metrics.md); at 1280x720, the least number of interleaved pairs
  int warmup = 2;   // at least; at 1280x720 warm-up goes on until the frame time settles
  // The timing mode's settings (set_timing_mode), each of which an option may override:
  // rounds the figures are timed in at 1280x720 (--rounds; pass 2 of run_bench), each in a
  // session of its own;
  int rounds = 5;
  double min_time_s = 0.5;  // at 1280x720, the least measuring time of each path (--min-time)
  // beyond it, pairs go on while the ratio's 95% interval is wider than +-target_interval
  // (--target-interval, a fraction), up to max_time_s of the path (--max-time).
  double target_interval = 0.02;
  double max_time_s = 2.5;
  TimingMode timing_mode = TimingMode::Precise;  // for the report
  std::vector<std::string> timing_overrides;     // for the report: options that changed the mode
  std::string llvmpipe_threads = "as the environment says";  // for the report (--lp-threads)
  std::string pinning = "not pinned";                        // for the report (--pin-core)
  unsigned cpu_threads = 0;  // for the report: the CPU paths' workers (--cpu-threads)
  int wide_width = 1280, wide_height = 720;
  bool quiet = false;          // no progress lines and no notes (--quiet)
  bool live_progress = false;  // a progress line redrawn in place (stderr is a terminal)
  std::string profile;  // --profile: the paths that take one split their programs into passes
};

struct FrameTiming {
  double median_ms = 0, min_ms = 0;
};

struct BenchRow {
  std::string scene, path, variant;
  FrameTiming at_scene_size, at_wide;
  double ratio_to_flat = 0;  // at 1280x720: the median of interleaved per-pair ratios
  RatioEstimate ratio;       // the same, with its 95% interval and pair count
  std::size_t settling_frames =
      0;           // flat frames run untimed after a path frame (interleaved_timing.h)
  int rounds = 0;  // sessions the row was timed in at 1280x720 (flat: those of its scene)
  std::optional<ErrorStats> error;  // covered pixels against the reference (none for flat)
  // Its pixels over 1 LSB classed (metrics' split_edge_shifts, as `compare` and `regress` class
  // them): a silhouette two rasterisers place differently reads as edge shifts, a wrong shade
  // as shading, so a large max is told from a broken shade. With `error`.
  std::optional<EdgeShiftSplit> edge_split;
  FrameStats stats;  // the path's own figures, medians over the timed frames
  std::optional<double> shading_mpixels_per_s;  // CPU paths: covered pixels / shading time
  std::string cost;                             // Path::cost(): instructions or stages
  // A console path's (writes_fifo_log) bytes and vertices a frame, from its budget of the
  // scene and variant (console_bytes.h); none for the other paths.
  std::optional<ConsoleBytes> console;
  std::optional<FrameWork> work;  // at 1280x720: operations a frame executes (frame_work.h)
  std::string work_not_counted;   // why `work` is empty
  std::string image, heatmap;     // relative to out_dir
  int width = 0, height = 0;      // of the image
};

// Sets rounds, min_time_s, target_interval, max_time_s and timing_mode to the mode's values.
void set_timing_mode(BenchOptions& options, TimingMode mode);

// The scenes, loaded, after checking every --paths name and that no added variant is a row the
// bench makes anyway: what run_bench reads before it writes anything (and `bench --jobs` before
// it starts a job). Throws InputError.
std::vector<Scene> load_bench_inputs(const BenchOptions& options);

std::vector<BenchRow> run_bench(const BenchOptions& options);

// report.md, report.csv, report.json, chart.svg, contact.png and index.html under out_dir.
void write_bench_reports(const BenchOptions& options, const std::vector<BenchRow>& rows);

// Median and min of a list of frame times (for tests).
FrameTiming summarize_frames(std::vector<double> frame_ms);

}  // namespace lt
