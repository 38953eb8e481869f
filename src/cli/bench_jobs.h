// `bench --jobs N`: one bench's scenes shared out over N processes of ltrender itself, a scene
// at a time each, each pinned to a core of its own; their rows make one report.
//
// Why processes and not threads: a job is a whole bench of one scene (its GL context, the CPU
// paths' workers, the path caches), exactly what `bench SCENE` runs alone; a thread would share
// all of that state with the other job. Why each on its own core: the bench's timing pins to one
// core (core/cpu_affinity.h); N jobs on N cores keep that, each timing its pairs with flat on its
// core, while the other cores do the other scenes. What that costs the figures (two jobs share
// the memory bus and the last-level cache) is measured in docs/bench.md "Jobs".
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "report/bench.h"

namespace lt::cli {

// The hidden options that make a bench process one job of another (cmd_bench.cpp adds them).
struct BenchJobRole {
  int scene = -1;             // index into the parent's scene list; -1: not a job
  int core = -1;              // the core to pin to; -1: not pinned
  std::filesystem::path dir;  // the parent's staging directory: images there, rows in .jobs/
  bool is_job() const { return scene >= 0; }
};

// The file a job writes its rows to (report.json's form), under the parent's staging directory.
std::filesystem::path job_rows_file(const std::filesystem::path& dir, int scene);

// Which core each of `jobs` jobs is pinned to (-1 each when --pin-core is `none`). Throws
// InputError when the jobs cannot each have a core of their own, or --pin-core names one core.
std::vector<int> job_cores(int jobs, const std::string& pin_core);

// Runs one job process per scene of `options.scenes`, at most cores.size() at a time, the k-th
// running on cores[k]; every job parses this process's own command line plus its role, and
// writes its images into `staging` (report/bench.h's images/). Returns the rows in scene order;
// `report` gets the jobs' pinning, llvmpipe and CPU-thread figures. A job that fails stops the
// others; its output is printed and the error thrown.
std::vector<BenchRow> run_bench_jobs(const BenchOptions& options, const std::vector<int>& cores,
                                     const std::filesystem::path& staging, BenchOptions& report);

}  // namespace lt::cli
