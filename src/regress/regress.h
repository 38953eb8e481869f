// `ltrender regress`: offscreen regression renders of a studio's own scenes against goldens.
// Every scene x path x variant is rendered, compared with its golden by the metrics library
// (metrics/compare.h: the figures, then an idiff-style verdict against the case's tolerance),
// and reported as one line each, and optionally as JUnit XML, JSON and the report page.
// `--update` writes the goldens that are missing or fail. ltrender's own golden test
// (tests/golden_test.cpp) and scripts/update_goldens.sh run through here.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "load/load_scene.h"
#include "metrics/compare.h"
#include "regress/regress_case.h"
#include "regress/shard.h"

namespace lt {

struct RegressOptions {
  std::vector<std::filesystem::path> inputs;  // scene files and folders of scenes
  SceneOptions scene_options;                 // --lights
  std::filesystem::path goldens;
  // The renderer's key (golden_key.h): its approved overrides are in goldens/KEY/. Empty: the
  // shared goldens only.
  std::string golden_key;
  std::string paths;  // the --paths list (regress_case.h); empty: every path but flat
  bool update = false;
  Shard shard;
  int width = 0, height = 0;  // > 0: render at this size instead of the scene's
  std::filesystem::path junit_file, json_file, report_dir;  // empty: not written
  bool quiet = false;                                       // no line per passing case
  // Isolation (docs/regress.md "A case that crashes or hangs"): with a worker command, the cases
  // run in `jobs` worker processes of it, each running many cases and replaced when one dies, so
  // a crash or a case over `case_timeout_seconds` (0: none) is that case's failure. Without one
  // (the library's own tests), in this process.
  std::vector<std::string> worker_command;  // executable, then its arguments
  // A platform's name (`--label`): in the JUnit's class names, so that two platforms' runs in
  // one pipeline keep their cases apart, and in the JSON and the page.
  std::string label;
  int jobs = 1;
  double case_timeout_seconds = 0;
  // --artifacts: whose images the report folder keeps (render, golden copy, heatmap): every
  // case's (the default), failing and warned cases' only, or none (the page has the figures).
  enum class Artifacts { kAll, kFailures, kNone };
  Artifacts artifacts = Artifacts::kAll;
};

// --artifacts all|failures|none; throws InputError naming --artifacts for another value.
RegressOptions::Artifacts parse_artifacts(const std::string& value);

enum class CaseStatus {
  kPass,
  kWarn,     // within tolerance, but over the warn tier (idiff's -warn): the golden moved
  kFail,     // over tolerance, or a golden of another size
  kCrashed,  // the worker process rendering it died (isolated runs)
  kTimedOut,  // it ran past --case-timeout and its worker was stopped
  kMissing,  // no golden: the message holds the command that creates it
  kSkipped,  // the variant cannot be exact for this scene
  kCreated,  // --update: the golden was missing and is written
  kUpdated,  // --update: the golden failed and is rewritten
  kKept,     // --update: the golden is within tolerance and left as it was
};
// Every status, failures first (the order the summary lists them in).
inline constexpr CaseStatus kCaseStatuses[] = {
    CaseStatus::kFail,    CaseStatus::kCrashed, CaseStatus::kTimedOut, CaseStatus::kMissing,
    CaseStatus::kWarn,    CaseStatus::kPass,    CaseStatus::kSkipped,  CaseStatus::kCreated,
    CaseStatus::kUpdated, CaseStatus::kKept};
const char* to_string(CaseStatus status);
// Throws InputError(file, where, ...) for a name to_string does not give.
CaseStatus case_status_from_string(const std::string& name, const std::string& file,
                                   const std::string& where);
// kFail, kCrashed, kTimedOut and kMissing: what makes the run exit 1.
bool is_failure(CaseStatus status);

struct CaseResult {
  RegressCase regress_case;
  CaseStatus status = CaseStatus::kPass;
  std::filesystem::path golden;       // the golden file of the case
  std::optional<ErrorStats> figures;  // the region the tolerance judges; none without a golden
  Verdict verdict;
  nlohmann::ordered_json comparison_json;  // metrics' to_json; null without a comparison
  std::string message;  // one line: the figures, the reasons, or the command to run
  std::string details;  // metrics' to_table; empty without a comparison
  double seconds = 0;   // render and compare
  int width = 0, height = 0;
  // Relative to the report dir, written only with one: render, golden copy, heatmap.
  std::string image, golden_image, heatmap;
};

struct RegressRun {
  std::vector<CaseResult> results;  // this shard's finished cases, in list order
  size_t total_cases = 0;           // over every shard
  size_t shard_cases = 0;           // this shard's, finished or not
  bool complete = false;            // every case of the shard finished
  Shard shard;
  // What the run is over, as the JSON states it: every shard of one run has the same, which
  // `regress merge` checks. The scenes' names in order, each PATH:VARIANT asked, the size.
  std::vector<std::string> scenes, requested;
  std::vector<std::string> scene_files;  // as given, in the scenes' order (CI annotations)
  int width = 0, height = 0;
  double seconds = 0;
  size_t count(CaseStatus status) const;
  bool failed() const;
};

// Reads and checks every input first: a bad scene, path list or output path, a --goldens folder
// that does not exist (without --update), or a scene one of the paths refuses when it is built
// throws InputError before anything is rendered or written. Prints one line per case (to
// stdout) unless quiet.
RegressRun run_regress(const RegressOptions& options);

// --junit, --json and the report page (-o), each written atomically; what the options name.
// run_regress writes the JUnit and the JSON as the cases finish too (streamed_outputs.h).
void write_regress_outputs(const RegressOptions& options, const RegressRun& run);
void write_regress_junit_and_json(const RegressOptions& options, const RegressRun& run);

// One line: how many cases passed, failed, ... and how long the run took.
std::string regress_summary(const RegressOptions& options, const RegressRun& run);

// The command that creates or refreshes one case's golden.
std::string update_command(const RegressOptions& options, const RegressCase& regress_case,
                           const std::filesystem::path& scene_file);

}  // namespace lt
