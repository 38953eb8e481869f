#include <algorithm>
#include <iostream>
#include <sstream>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "report/bench.h"

namespace lt::cli {

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
  sub->add_option("-o,--output", *out, "Output directory")->required();
  sub->add_flag("--quiet", o->quiet, "No progress lines");
  return [o, scenes, paths, out]() -> int {
    o->out_dir = *out;
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
    });
    std::cout << "bench: " << rows.size() << " rows -> " << (o->out_dir / "report.md").string()
              << "\n";
    return 0;
  };
}

}  // namespace lt::cli
