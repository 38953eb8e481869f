// `ltrender regress SCENE_OR_DIR... --goldens DIR`: regression renders against goldens (docs/
// regress.md). Exit 0 every case passed (or --update wrote what was needed), 1 some
// failed or have no golden, 2 bad input. All the work is in regress/; this file reads options.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "cli/lights_option.h"
#include "cli/own_arguments.h"
#include "cli/threads_option.h"
#include "core/error.h"
#include "regress/github_actions.h"
#include "regress/golden_key.h"
#include "regress/merge.h"
#include "regress/regress.h"
#include "regress/regress_workers.h"

namespace lt::cli {

Action add_regress(CLI::App& app) {
  auto o = std::make_shared<RegressOptions>();
  auto inputs = std::make_shared<std::vector<std::string>>();
  auto shard = std::make_shared<std::string>("1/1");
  auto goldens = std::make_shared<std::string>();
  auto junit = std::make_shared<std::string>();
  auto json = std::make_shared<std::string>();
  auto report = std::make_shared<std::string>();
  auto* sub = app.add_subcommand(
      "regress", "Render scenes through paths and compare each image with its golden");
  // Both required unless `regress merge` runs instead (checked when the run starts).
  sub->add_option("SCENE_OR_DIR", *inputs, "Scene files, or folders of them (their *.json)");
  sub->add_option("--goldens", *goldens,
                  "Folder of goldens: SCENE__PATH[__VARIANT].png; it must exist unless --update "
                  "(which creates it)");
  sub->add_option("--paths", o->paths,
                  "Comma-separated PATH (default variant), PATH:VARIANT or PATH:* (every "
                  "variant); default: every path but flat");
  sub->add_flag("--update", o->update,
                "Write the goldens that are missing or fail, and list them (created: the file "
                "written; updated: the figures that moved it)");
  sub->add_option("--junit", *junit, "Write JUnit XML (one testcase per scene, path, variant)");
  sub->add_option("--json", *json, "Write every case's figures as JSON");
  sub->add_option("--shard", *shard, "Run shard I of N of the cases (1-based), e.g. 2/4")
      ->capture_default_str();
  sub->add_option("-o,--output", *report, "Report folder: index.html and its images");
  sub->add_option("--width", o->width, "Render at this width instead of the scene's")
      ->check(CLI::Range(1, 16384));
  sub->add_option("--height", o->height, "Render at this height instead of the scene's")
      ->check(CLI::Range(1, 16384));
  sub->add_flag("--quiet", o->quiet, "No line per passing case");
  sub->add_option("--jobs", o->jobs,
                  "Worker processes that render the cases, each many cases (a crash or a hang "
                  "costs its case, not the run); 0: every case in this process, unprotected")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  sub->add_option("--case-timeout", o->case_timeout_seconds,
                  "Seconds a case may take before its worker is stopped and the case is 'timed "
                  "out'; 0: no deadline")
      ->check(CLI::Range(0.0, 1e6))
      ->capture_default_str();
  auto worker_fd = std::make_shared<int>(-1);
  // Hidden (no group): what makes a process one of the run's workers (regress/regress_workers.h).
  sub->add_option(kRegressWorkerOption, *worker_fd)->group("");
  auto* golden_key = sub->add_option(
      "--golden-key", o->golden_key,
      "The renderer's key: its approved overrides are in GOLDENS/KEY/ (default: from the GL "
      "renderer and Mesa version, e.g. llvmpipe-mesa-22.3.6); 'none': the shared goldens alone, "
      "which --update then rewrites");
  sub->add_option("--label", o->label,
                  "A platform's name for the JUnit's class names (regress.LABEL.SCENE), the JSON "
                  "and the page: two platforms' cases stay apart in one pipeline");
  add_lights_option(sub, o->scene_options);
  auto artifacts = std::make_shared<std::string>("all");
  sub->add_option("--artifacts", *artifacts,
                  "Whose images the report folder (-o) keeps: all, failures (failing and warned "
                  "cases), none")
      ->capture_default_str();
  auto ci = std::make_shared<std::string>("auto");
  sub->add_option("--ci", *ci,
                  "github: ::error/::warning annotations per failing/warned case and a table "
                  "appended to $GITHUB_STEP_SUMMARY; none; auto: github when GITHUB_ACTIONS=true")
      ->capture_default_str();

  auto m = std::make_shared<MergeOptions>();
  auto merge_label = std::make_shared<std::string>();
  auto* merge = sub->add_subcommand(
      "merge", "Merge the --json of every shard of one run into one JSON, JUnit and page");
  merge->add_option("SHARD.json", m->shards, "The --json of each shard (regress --shard I/N)")
      ->required();
  merge->add_option("-o,--output", m->report_dir, "Report folder: index.html and its images");
  merge->add_option("--junit", m->junit_file, "Write the merged JUnit XML");
  merge->add_option("--json", m->json_file, "Write the merged JSON");
  auto* label_option =
      merge->add_option("--label", *merge_label, "A platform's name, instead of the shards' own");
  auto merge_ci = std::make_shared<std::string>("auto");
  merge->add_option("--ci", *merge_ci, "As regress's --ci, for the merged run")
      ->capture_default_str();
  add_threads_option(sub);
  return [o, inputs, shard, goldens, junit, json, report, worker_fd, m, merge, merge_label,
          label_option, golden_key, artifacts, ci, merge_ci]() -> int {
    if (merge->parsed()) {
      if (label_option->count() > 0) m->label = *merge_label;
      const bool github = github_ci_wanted(*merge_ci);
      RegressOptions as_run;
      const RegressRun run = merge_regress_shards(*m, as_run);
      write_regress_outputs(as_run, run);
      std::printf("regress merge: %s\n", regress_summary(as_run, run).c_str());
      if (github) report_to_github(as_run, run);
      return run.failed() ? 1 : 0;
    }
    if (inputs->empty()) throw InputError("SCENE_OR_DIR", "", "no scene given");
    if (goldens->empty()) throw InputError("--goldens", "", "a folder of goldens is required");
    if (!o->label.empty()) check_name_option("--label", o->label);
    if (golden_key->count() > 0) {
      check_name_option("--golden-key", o->golden_key);
      if (o->golden_key == "none") o->golden_key.clear();  // the shared goldens alone
    } else {
      o->golden_key = renderer_golden_key();
    }
    o->inputs.assign(inputs->begin(), inputs->end());
    o->goldens = *goldens;
    o->junit_file = *junit;
    o->json_file = *json;
    o->report_dir = *report;
    o->shard = parse_shard(*shard);
    o->artifacts = parse_artifacts(*artifacts);
    if (*worker_fd >= 0) return run_regress_worker(*o, *worker_fd);
    const bool github = github_ci_wanted(*ci);
    if (o->jobs > 0) {
      o->worker_command = {std::filesystem::read_symlink("/proc/self/exe").string()};
      for (const std::string& a : own_arguments()) o->worker_command.push_back(a);
    }
    const RegressRun run = run_regress(*o);
    write_regress_outputs(*o, run);
    std::printf("regress: %s\n", regress_summary(*o, run).c_str());
    if (!o->report_dir.empty())
      std::printf("regress: report page %s\n", (o->report_dir / "index.html").c_str());
    if (github) report_to_github(*o, run);
    return run.failed() ? 1 : 0;
  };
}

}  // namespace lt::cli
