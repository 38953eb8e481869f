#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/parallel_rows.h"
#include "report/bench.h"
#include "report/bench_compare.h"

namespace lt::cli {

namespace {

// What llvmpipe will use, for the report: LP_NUM_THREADS is read when the first context is made,
// so --lp-threads sets it before any. The CPU paths' own threads never run while llvmpipe
// renders (they shade after the G-buffer's read-back), so the two do not compete in a frame.
std::string llvmpipe_threads(int requested) {
  if (requested > 0) {
    ::setenv("LP_NUM_THREADS", std::to_string(requested).c_str(), 1);
    return "LP_NUM_THREADS=" + std::to_string(requested) + " (--lp-threads)";
  }
  if (const char* env = std::getenv("LP_NUM_THREADS"))
    return std::string("LP_NUM_THREADS=") + env + " (from the environment)";
  return "llvmpipe's default, one per core (" +
         std::to_string(std::thread::hardware_concurrency()) + ")";
}

}  // namespace

Action add_bench(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  auto scenes = std::make_shared<std::vector<std::string>>();
  auto paths = std::make_shared<std::string>();
  auto out = std::make_shared<std::string>();
  auto* sub = app.add_subcommand("bench", "Speed against error: scenes x paths x variants");
  sub->add_option("SCENE", *scenes, "Scene files (default: scenes/*.json of the source tree)");
  sub->add_option("--paths", *paths, "Comma-separated paths (default: all; flat always runs)");
  sub->add_option("--frames", o->frames, "Timed frames per measurement (>= 10)")
      ->check(CLI::Range(10, 100000));
  sub->add_option("--warmup", o->warmup, "Warm-up frames (at least; at 1280x720 until settled)")
      ->check(CLI::Range(0, 1000));
  sub->add_option("--min-time", o->min_time_s,
                  "Least measuring time per path at 1280x720, in seconds (interleaved with flat)")
      ->check(CLI::Range(0.0, 60.0));
  auto compare_with = std::make_shared<std::string>();
  sub->add_option("--compare", *compare_with,
                  "An earlier report.json: rows whose ratio intervals do not overlap are listed "
                  "in compare.md; exit 1 if any is slower");
  auto lp_threads = std::make_shared<int>(0);
  sub->add_option("--lp-threads", *lp_threads,
                  "llvmpipe's rendering threads (sets LP_NUM_THREADS; default: the environment's)")
      ->check(CLI::Range(1, 64));
  auto cpu_threads = std::make_shared<unsigned>(0);
  sub->add_option("--cpu-threads", *cpu_threads,
                  "Threads of the CPU paths' per-pixel stages (reference, half, gx; default: "
                  "one per core)")
      ->check(CLI::Range(1, 64));
  sub->add_option("-o,--output", *out, "Output directory")->required();
  sub->add_flag("--quiet", o->quiet, "No progress lines");
  sub->add_option("--profile", o->profile,
                  "arbfp: a profile (ps_2_0 ...) its programs must fit; materials over it are "
                  "drawn in additive passes (the cost column says how many)");
  return [o, scenes, paths, out, lp_threads, cpu_threads, compare_with]() -> int {
    worker_threads_setting() = *cpu_threads;
    o->out_dir = *out;
    // The earlier report is read first: a bad one fails before the bench runs.
    std::optional<EarlierBench> before;
    if (!compare_with->empty()) before = read_earlier_bench(*compare_with);
    o->llvmpipe_threads = llvmpipe_threads(*lp_threads);
    o->paths.clear();
    std::stringstream ss(*paths);
    for (std::string p; std::getline(ss, p, ',');) {
      if (!p.empty()) o->paths.push_back(p);
    }
    o->scenes.clear();
    for (const auto& s : *scenes) o->scenes.push_back(s);
    if (o->scenes.empty()) {
      for (const auto& e : fs::directory_iterator(fs::path(LT_SOURCE_DIR) / "scenes")) {
        if (e.path().extension() == ".json") o->scenes.push_back(e.path());
      }
      std::sort(o->scenes.begin(), o->scenes.end());
    }
    // Images and reports appear together or not at all (core/fs.h): a killed bench leaves the
    // previous run's directory as it was.
    std::vector<BenchRow> rows;
    write_directory_atomically(o->out_dir, [&](const fs::path& staging) {
      BenchOptions staged = *o;
      staged.out_dir = staging;
      rows = run_bench(staged);
      write_bench_reports(staged, rows);
      if (before) {
        write_text_file(staging / "compare.md",
                        comparison_markdown(*before, compare_bench(*before, rows)));
      }
    });
    std::cout << "bench: " << rows.size() << " rows -> " << (o->out_dir / "report.md").string()
              << "\n";
    if (before) {
      const BenchComparison c = compare_bench(*before, rows);
      std::cout << "bench: against " << *compare_with << ": " << c.changed.size() << " changed, "
                << c.slower() << " slower -> " << (o->out_dir / "compare.md").string() << "\n";
      if (c.slower() > 0) {
        std::string names;
        for (const auto& r : c.changed)
          if (r.slower())
            names += (names.empty() ? "" : ", ") + r.scene + " " + r.path + " " + r.variant;
        throw CheckFailed("bench: " + std::to_string(c.slower()) + " rows slower than " +
                          *compare_with + ": " + names);
      }
    }
    return 0;
  };
}

}  // namespace lt::cli
