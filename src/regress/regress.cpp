#include "regress/regress.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>

#include "core/error.h"
#include "core/fs.h"
#include "core/stopwatch.h"
#include "regress/regress_plan.h"
#include "regress/regress_workers.h"
#include "regress/run_case.h"

namespace lt {

namespace {

void print_case(const RegressOptions& o, const CaseResult& r) {
  if (o.quiet && !is_failure(r.status) && r.status != CaseStatus::kCreated &&
      r.status != CaseStatus::kUpdated)
    return;
  // Failures in capitals, so that they stand out in a CI log.
  std::string status = to_string(r.status);
  if (is_failure(r.status))
    for (char& ch : status) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  std::printf("%-7s %s%s%s\n", status.c_str(), r.regress_case.id().c_str(),
              r.message.empty() ? "" : ": ", r.message.c_str());
  std::fflush(stdout);
}

// The run's results as they come: each printed, kept in list order, and the JUnit and JSON
// rewritten (each atomically) so that a run that is killed leaves both valid with every case
// finished a moment before. Rewriting every file after every case would cost the square of the
// case count; so a write waits at least half a second after the last, and ten times as long as
// the last took, which keeps the writes under a tenth of the run whatever its size.
class RunCollector {
 public:
  RunCollector(const RegressOptions& o, SteadyClock::time_point t0) : o_(o), t0_(t0) {}

  void add(size_t position, CaseResult r) {
    print_case(o_, r);
    const auto at = std::upper_bound(positions_.begin(), positions_.end(), position);
    run.results.insert(run.results.begin() + (at - positions_.begin()), std::move(r));
    positions_.insert(at, position);
    unwritten_ = true;
    write_if_due();
  }

  void write_if_due() {
    if (!unwritten_ || (o_.junit_file.empty() && o_.json_file.empty())) return;
    const auto now = SteadyClock::now();
    if (now - last_write_ < std::max(std::chrono::duration<double>(0.5), 10 * last_write_took_))
      return;
    run.seconds = seconds_since(t0_);
    write_regress_junit_and_json(o_, run);
    last_write_ = SteadyClock::now();
    last_write_took_ = last_write_ - now;
    unwritten_ = false;
  }

  RegressRun run;

 private:
  const RegressOptions& o_;
  SteadyClock::time_point t0_;
  std::vector<size_t> positions_;  // of run.results, ascending
  bool unwritten_ = false;
  SteadyClock::time_point last_write_{};
  std::chrono::duration<double> last_write_took_{0};
};

}  // namespace

const char* to_string(CaseStatus s) {
  switch (s) {
    case CaseStatus::kPass:
      return "pass";
    case CaseStatus::kWarn:
      return "warn";
    case CaseStatus::kCrashed:
      return "crashed";
    case CaseStatus::kTimedOut:
      return "timed out";
    case CaseStatus::kFail:
      return "fail";
    case CaseStatus::kMissing:
      return "missing";
    case CaseStatus::kSkipped:
      return "skipped";
    case CaseStatus::kCreated:
      return "created";
    case CaseStatus::kUpdated:
      return "updated";
    case CaseStatus::kKept:
      return "kept";
  }
  return "?";
}

CaseStatus case_status_from_string(const std::string& name, const std::string& file,
                                   const std::string& where) {
  for (CaseStatus s : kCaseStatuses) {
    if (name == to_string(s)) return s;
  }
  throw InputError(file, where, "unknown case status '" + name + "'");
}

RegressOptions::Artifacts parse_artifacts(const std::string& value) {
  if (value == "all") return RegressOptions::Artifacts::kAll;
  if (value == "failures") return RegressOptions::Artifacts::kFailures;
  if (value == "none") return RegressOptions::Artifacts::kNone;
  throw InputError("--artifacts", value, "must be all, failures or none");
}

bool is_failure(CaseStatus s) {
  return s == CaseStatus::kFail || s == CaseStatus::kMissing || s == CaseStatus::kCrashed ||
         s == CaseStatus::kTimedOut;
}

size_t RegressRun::count(CaseStatus s) const {
  size_t n = 0;
  for (const CaseResult& r : results) n += r.status == s;
  return n;
}

bool RegressRun::failed() const {
  return std::any_of(results.begin(), results.end(),
                     [](const CaseResult& r) { return is_failure(r.status); });
}

std::string update_command(const RegressOptions& o, const RegressCase& c,
                           const fs::path& scene_file) {
  std::string cmd = "ltrender regress " + scene_file.string() + " --goldens " + o.goldens.string() +
                    " --paths '" + c.path->name + ":" + c.variant + "'";
  if (o.width > 0) cmd += " --width " + std::to_string(o.width);
  if (o.height > 0) cmd += " --height " + std::to_string(o.height);
  if (!o.scene_options.default_lights) cmd += " --lights none";
  return cmd + " --update";
}

RegressRun run_regress(const RegressOptions& o) {
  const auto t0 = SteadyClock::now();
  const RegressPlan plan = make_regress_plan(o);
  std::vector<size_t> mine;  // this shard's positions in the case list
  for (size_t i = 0; i < plan.cases.size(); ++i) {
    if (o.shard.takes(i)) mine.push_back(i);
  }
  if (!o.report_dir.empty()) make_directory(o.report_dir / "images");
  if (o.update) make_directory(o.goldens);

  RunCollector collector(o, t0);
  collector.run.shard = o.shard;
  collector.run.total_cases = plan.cases.size();
  collector.run.shard_cases = mine.size();
  for (const fs::path& f : plan.scene_files) {
    collector.run.scenes.push_back(f.stem().string());
    collector.run.scene_files.push_back(f.string());
  }
  for (const PathRequest& r : parse_path_list(o.paths)) {
    for (const std::string& v : r.variants) collector.run.requested.push_back(r.path->name + ":" + v);
  }
  collector.run.width = o.width;
  collector.run.height = o.height;
  const auto done = [&](size_t position, CaseResult r) { collector.add(position, std::move(r)); };
  if (o.worker_command.empty()) {
    // In this process, a scene at a time, so that each scene is set up once.
    std::map<size_t, std::vector<size_t>> by_scene;
    for (size_t i : mine) by_scene[plan.cases[i].scene_index].push_back(i);
    for (const auto& [scene_index, positions] : by_scene) {
      const Scene& scene = plan.scenes[scene_index];
      std::optional<RenderSession> session;
      for (size_t i : positions) {
        const RegressCase& c = plan.cases[i];
        if (!c.skip_reason.empty()) {
          done(i, skipped_case(o, c));
          continue;
        }
        if (!session) {
          session.emplace(scene, o.width > 0 ? o.width : scene.width,
                          o.height > 0 ? o.height : scene.height);
        }
        done(i, run_case(o, plan.scene_files[scene_index], *session, c));
      }
    }
  } else {
    std::vector<size_t> rendered;
    for (size_t i : mine) {
      if (plan.cases[i].skip_reason.empty()) {
        rendered.push_back(i);
      } else {
        done(i, skipped_case(o, plan.cases[i]));
      }
    }
    run_in_workers(o, plan, rendered, done, [&] { collector.write_if_due(); });
  }
  collector.run.complete = true;
  collector.run.seconds = seconds_since(t0);
  write_regress_junit_and_json(o, collector.run);
  return std::move(collector.run);
}

}  // namespace lt
