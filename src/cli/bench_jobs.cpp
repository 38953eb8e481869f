#include "cli/bench_jobs.h"

#include <csignal>
#include <fstream>
#include <iterator>
#include <memory>
#include <sstream>

#include "cli/own_arguments.h"
#include "core/child_process.h"
#include "core/cpu_affinity.h"
#include "core/error.h"
#include "report/bench_json.h"
#include "report/bench_progress.h"

namespace lt::cli {

namespace {

std::string read_log(const std::filesystem::path& log) {
  std::ifstream in(log);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::string core_list(const std::vector<int>& cores) {
  std::string s;
  for (int c : cores) s += (s.empty() ? "" : ", ") + std::to_string(c);
  return s;
}

struct RunningJob {
  std::unique_ptr<ChildProcess> process;
  int scene = -1;
};

}  // namespace

std::filesystem::path job_rows_file(const std::filesystem::path& dir, int scene) {
  return dir / ".jobs" / (std::to_string(scene) + ".json");
}

std::vector<int> job_cores(int jobs, const std::string& pin_core) {
  if (pin_core == "none") return std::vector<int>(static_cast<std::size_t>(jobs), -1);
  if (pin_core != "last") {
    throw InputError("--pin-core", "",
                     "'" + pin_core +
                         "' names one core, but with --jobs each job is pinned to a core of its "
                         "own: give 'last' (the default) or 'none'");
  }
  const std::vector<int> allowed = allowed_cores();
  if (static_cast<std::size_t>(jobs) > allowed.size()) {
    throw InputError("--jobs", "",
                     std::to_string(jobs) +
                         " jobs, each pinned to a core of its own, but this "
                         "process may use " +
                         std::to_string(allowed.size()) + " (" + core_list(allowed) +
                         "): give at most that, or --pin-core none");
  }
  // The last cores, as a single bench takes the last one.
  return std::vector<int>(allowed.end() - jobs, allowed.end());
}

std::vector<BenchRow> run_bench_jobs(const BenchOptions& o, const std::vector<int>& cores,
                                     const std::filesystem::path& staging, BenchOptions& report) {
  std::filesystem::create_directories(staging / ".jobs");
  const std::vector<std::string> args = own_arguments();
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe");
  BenchProgress progress(o.live_progress && !o.quiet, !o.quiet);
  progress.start_phase("scenes, " + std::to_string(cores.size()) + " jobs", o.scenes.size());

  std::vector<RunningJob> slots(cores.size());
  auto log_of = [&](int scene) { return staging / ".jobs" / (std::to_string(scene) + ".log"); };
  auto start = [&](std::size_t slot, int scene) {
    ChildProgram p;
    p.executable = self;
    p.arguments = args;
    p.arguments.insert(p.arguments.end(),
                       {"--job-scene", std::to_string(scene), "--job-core",
                        std::to_string(cores[slot]), "--job-dir", staging.string()});
    p.output = log_of(scene);
    progress.step(o.scenes[static_cast<std::size_t>(scene)].stem().string());
    slots[slot] = {std::make_unique<ChildProcess>(p), scene};
  };
  // A job's end: its notes (variants a scene skips) go on to the user; a failure stops the rest.
  auto finish = [&](RunningJob& job) {
    job.process->stop(SIGTERM, std::chrono::milliseconds(0));
    const int status = job.process->wait_status();
    const std::string log = read_log(log_of(job.scene));
    std::istringstream lines(log);
    const bool failed = !(WIFEXITED(status) && WEXITSTATUS(status) == 0);
    if (failed) {
      for (RunningJob& other : slots) {
        if (other.process) other.process->stop(SIGTERM, std::chrono::milliseconds(500));
      }
      std::fputs(log.c_str(), stderr);
      throw std::runtime_error("bench --jobs: the job of " +
                               o.scenes[static_cast<std::size_t>(job.scene)].string() + " " +
                               describe_wait_status(status) + " (its output is above)");
    }
    for (std::string line; std::getline(lines, line);) progress.note(line);
    job.process.reset();
  };

  int next = 0;
  const int scenes = static_cast<int>(o.scenes.size());
  for (;;) {
    for (std::size_t k = 0; k < slots.size() && next < scenes; ++k) {
      if (!slots[k].process) start(k, next++);
    }
    bool any = false;
    for (RunningJob& job : slots) {
      if (!job.process) continue;
      any = true;
      if (job.process->wait_until(ChildProcess::Clock::now() + std::chrono::milliseconds(50)))
        finish(job);
    }
    if (!any && next >= scenes) break;
  }

  std::vector<BenchRow> rows;
  for (int s = 0; s < scenes; ++s) {
    BenchReportFile f = read_bench_report(job_rows_file(staging, s));
    if (s == 0) {
      report.llvmpipe_threads = f.llvmpipe_threads;
      report.cpu_threads = f.cpu_threads;
    }
    rows.insert(rows.end(), f.rows.begin(), f.rows.end());
  }
  std::filesystem::remove_all(staging / ".jobs");
  report.pinning =
      std::to_string(cores.size()) + " jobs (bench --jobs), a scene at a time each" +
      (cores.front() < 0 ? ", not pinned"
                         : ", each pinned to a core of its own (" + core_list(cores) + ")");
  return rows;
}

}  // namespace lt::cli
