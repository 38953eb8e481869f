#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>

#include "cli/bench_jobs.h"
#include "cli/bench_timing_options.h"
#include "cli/commands.h"
#include "cli/lights_option.h"
#include "core/cpu_affinity.h"
#include "core/error.h"
#include "core/fs.h"
#include "core/parallel_rows.h"
#include "core/run_time_files.h"
#include "report/bench.h"
#include "report/bench_compare.h"
#include "report/bench_json.h"

namespace lt::cli {

namespace {

// What llvmpipe will use, for the report: LP_NUM_THREADS is read when the first context is made,
// so --lp-threads sets it before any. The CPU paths' own threads never run while llvmpipe
// renders (they shade after the G-buffer's read-back), so the two do not compete in a frame.
// Pinned to one core, llvmpipe rasterises in the calling thread (LP_NUM_THREADS=0) unless told
// otherwise: threads sharing one core would only add hand-offs.
std::string llvmpipe_threads(int requested, bool pinned) {
  if (requested >= 0) {
    ::setenv("LP_NUM_THREADS", std::to_string(requested).c_str(), 1);
    return "LP_NUM_THREADS=" + std::to_string(requested) + " (--lp-threads)";
  }
  if (const char* env = std::getenv("LP_NUM_THREADS"))
    return std::string("LP_NUM_THREADS=") + env + " (from the environment)";
  if (pinned) {
    ::setenv("LP_NUM_THREADS", "0", 1);
    return "LP_NUM_THREADS=0, rasterising in the calling thread (the bench is pinned to one core)";
  }
  return "llvmpipe's default, one per core (" +
         std::to_string(std::thread::hardware_concurrency()) + ")";
}

// --pin-core: `last` (the default) is the last core the process may use, `none` leaves the
// scheduler free, a number is that core. Returns what the report says.
std::string pin_to_core(const std::string& spec, bool& pinned) {
  pinned = false;
  const std::vector<int> allowed = allowed_cores();
  if (spec == "none" || allowed.empty())
    return "not pinned (" + std::to_string(usable_core_count()) + " cores)";
  int core = allowed.back();
  if (spec != "last") {
    std::size_t used = 0;
    try {
      core = std::stoi(spec, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != spec.size())
      throw InputError("--pin-core", "", "'" + spec + "' is not a core number, 'last' or 'none'");
  }
  if (!pin_process_to_core(core)) {
    std::string list;
    for (int c : allowed) {
      if (!list.empty()) list += ',';  // appended piecewise: GCC 12 warns falsely (-Wrestrict)
      list += std::to_string(c);       // on "" + std::string in the unity build
    }
    throw InputError("--pin-core", "",
                     "core " + spec + " is not one this process may use (" + list + ")");
  }
  pinned = true;
  return "pinned to core " + std::to_string(core) + " (--pin-core " + spec + ")";
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
  add_lights_option(sub, o->scene_options);
  sub->add_option("--frames", o->frames, "Timed frames per measurement (>= 10)")
      ->check(CLI::Range(10, 100000));
  sub->add_option("--warmup", o->warmup, "Warm-up frames (at least; at 1280x720 until settled)")
      ->check(CLI::Range(0, 1000));
  auto apply_timing = add_timing_options(*sub, *o);
  auto variants = std::make_shared<std::string>("all");
  sub->add_option("--variants", *variants,
                  "Which variants of each path: all (default), default (each path's first), "
                  "story (the default and those the docs compare it with: ./run.sh's run)")
      ->check(CLI::IsMember(variant_selections()));
  auto added = std::make_shared<std::vector<std::string>>();
  sub->add_option("--add-variant", *added,
                  "PATH:VARIANT, a row for a variant the path does not list (its name ends at "
                  "the first ':'), e.g. gx:t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:draw=list; "
                  "repeatable")
      ->allow_extra_args(false)
      ->take_all();
  auto compare_with = std::make_shared<std::string>();
  sub->add_option("--compare", *compare_with,
                  "An earlier report.json: rows whose ratio intervals do not overlap are listed "
                  "in compare.md; exit 1 if any is slower");
  auto lp_threads = std::make_shared<int>(-1);
  sub->add_option("--lp-threads", *lp_threads,
                  "llvmpipe's rendering threads (sets LP_NUM_THREADS; 0: in the calling thread; "
                  "default: the environment's, or 0 when pinned to one core)")
      ->check(CLI::Range(0, 64));
  auto pin_core = std::make_shared<std::string>("last");
  sub->add_option("--pin-core", *pin_core,
                  "Run the whole bench on one core: 'last' (default, the last core the process "
                  "may use), a core number, or 'none'");
  auto cpu_threads = std::make_shared<unsigned>(0);
  sub->add_option("--cpu-threads", *cpu_threads,
                  "Threads of the CPU paths' per-pixel stages (reference, half, gx; default: "
                  "one per core the bench may use: 1 when pinned)")
      ->check(CLI::Range(1, 64));
  auto jobs = std::make_shared<int>(1);
  sub->add_option("--jobs", *jobs,
                  "Share the scenes out over N processes, a scene at a time each, each pinned to "
                  "a core of its own (with --pin-core none: not pinned); one report")
      ->check(CLI::Range(1, 64));
  // A job of another bench (cli/bench_jobs.h): hidden, set only by the parent.
  auto role = std::make_shared<BenchJobRole>();
  sub->add_option("--job-scene", role->scene)->group("");
  sub->add_option("--job-core", role->core)->group("");
  sub->add_option("--job-dir", role->dir)->group("");
  sub->add_option("-o,--output", *out, "Output directory")->required();
  sub->add_flag("--quiet", o->quiet,
                "No progress line and no notes (the progress line is drawn only on a terminal)");
  sub->add_option("--profile", o->profile,
                  "arbfp: a profile (ps_2_0 ...) its programs must fit; materials over it are "
                  "drawn in additive passes (the cost column says how many)");
  return [o, scenes, paths, out, lp_threads, cpu_threads, pin_core, compare_with, apply_timing,
          variants, jobs, role, added]() -> int {
    apply_timing();
    o->variants = variant_selections().at(*variants);
    o->added_variants.clear();
    for (const std::string& text : *added) o->added_variants.push_back(parse_added_variant(text));
    // A line redrawn in place means nothing in a log: only a person at a terminal gets it.
    o->live_progress = ::isatty(STDERR_FILENO) == 1 && !role->is_job();
    // Before any thread or context exists: what is started later inherits the core. A parent
    // of jobs is not pinned (its jobs are, each to its own core) and renders nothing.
    bool pinned = false;
    std::vector<int> cores;
    if (role->is_job()) {
      o->pinning = role->core < 0 ? "not pinned" : pin_to_core(std::to_string(role->core), pinned);
    } else if (*jobs > 1) {
      cores = job_cores(*jobs, *pin_core);
    } else {
      o->pinning = pin_to_core(*pin_core, pinned);
    }
    worker_threads_setting() = *cpu_threads;
    o->out_dir = *out;
    // The earlier report is read first: a bad one fails before the bench runs.
    std::optional<EarlierBench> before;
    if (!compare_with->empty() && !role->is_job()) before = read_earlier_bench(*compare_with);
    o->llvmpipe_threads = llvmpipe_threads(*lp_threads, pinned);
    o->cpu_threads = worker_threads();
    o->paths.clear();
    std::stringstream ss(*paths);
    for (std::string p; std::getline(ss, p, ',');) {
      if (!p.empty()) o->paths.push_back(p);
    }
    o->scenes.clear();
    for (const auto& s : *scenes) o->scenes.push_back(s);
    if (o->scenes.empty()) {
      for (const auto& e : fs::directory_iterator(lt::run_time_files::data_dir() / "scenes")) {
        if (e.path().extension() == ".json") o->scenes.push_back(e.path());
      }
      std::sort(o->scenes.begin(), o->scenes.end());
    }
    if (role->is_job()) {
      // One scene of the parent's list, its images into the parent's staging directory, its rows
      // in report.json's form for the parent to read.
      BenchOptions job = *o;
      job.scenes = {o->scenes.at(static_cast<std::size_t>(role->scene))};
      job.out_dir = role->dir;
      write_text_file(job_rows_file(role->dir, role->scene),
                      bench_report_json(job, run_bench(job)).dump(2) + "\n");
      return 0;
    }
    // Every input is checked before the first job starts (a single bench does it in run_bench).
    if (!cores.empty()) load_bench_inputs(*o);
    // Images and reports appear together or not at all (core/fs.h): a killed bench leaves the
    // previous run's directory as it was.
    std::vector<BenchRow> rows;
    write_directory_atomically(o->out_dir, [&](const fs::path& staging) {
      BenchOptions staged = *o;
      staged.out_dir = staging;
      rows = cores.empty() ? run_bench(staged) : run_bench_jobs(staged, cores, staging, staged);
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
