// `ltrender regress SCENE_OR_DIR... --goldens DIR`: regression renders against goldens (docs/
// regress.md). Exit 0 every case passed (or --update wrote what was needed), 1 some
// failed or have no golden, 2 bad input. All the work is in regress/; this file reads options.
#include <cstdio>
#include <memory>

#include "cli/commands.h"
#include "cli/lights_option.h"
#include "cli/threads_option.h"
#include "regress/regress.h"

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
  sub->add_option("SCENE_OR_DIR", *inputs, "Scene files, or folders of them (their *.json)")
      ->required();
  sub->add_option("--goldens", *goldens,
                  "Folder of goldens: SCENE__PATH[__VARIANT].png; it must exist unless --update "
                  "(which creates it)")
      ->required();
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
  add_lights_option(sub, o->scene_options);
  add_threads_option(sub);
  return [o, inputs, shard, goldens, junit, json, report]() -> int {
    o->inputs.assign(inputs->begin(), inputs->end());
    o->goldens = *goldens;
    o->junit_file = *junit;
    o->json_file = *json;
    o->report_dir = *report;
    o->shard = parse_shard(*shard);
    const RegressRun run = run_regress(*o);
    write_regress_outputs(*o, run);
    std::printf("regress: %s\n", regress_summary(*o, run).c_str());
    if (!o->report_dir.empty())
      std::printf("regress: report page %s\n", (o->report_dir / "index.html").c_str());
    return run.failed() ? 1 : 0;
  };
}

}  // namespace lt::cli
