#include <iostream>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "paths/path.h"

namespace lt::cli {

namespace {

// The path whose program files end in `file`'s extension, or nullptr.
const PathInfo* path_of_program_file(const std::string& file) {
  const std::string ext = fs::path(file).extension().string();
  for (const PathInfo& p : all_paths()) {
    for (const std::string& e : p.program_extensions) {
      if (e == ext) return &p;
    }
  }
  return nullptr;
}

}  // namespace

// `ltrender budget SCENE [--path P] [--variant V] [--profile NAME] [--json]`: what path P builds
// for the scene, counted against the profile; `ltrender budget FILE` counts a program file of
// the path whose files end that way. Each path owns its counter and profiles (PathInfo::budget).
// Exit 1 when something is over, naming the limit.
Action add_budget(CLI::App& app) {
  auto* sub = app.add_subcommand("budget", "Check program/stage budgets against hardware profiles");
  auto scene = std::make_shared<std::string>();
  auto path = std::make_shared<std::string>("arbfp");
  auto request = std::make_shared<BudgetRequest>();
  sub->add_option("SCENE", *scene, "Scene file, or a program file (.c, .gx: a GX program)")
      ->required();
  sub->add_option("--path", *path,
                  "arbfp (programs), combiners (GL stages, units, passes) or gx (TEV stages, "
                  "texgens, channels, lights, passes)");
  sub->add_option("--variant", request->variant, "Path variant (default: the path's default)");
  sub->add_option("--profile", request->profile,
                  "arbfp: ps_2_0 (default), ps_2_x, arbfp1-min, vs_2_0, arbvp1-min (the partner "
                  "profile checks the other program kind); combiners: gl13-2units (default), "
                  "gl13-3units, gl-8units; gx: wii-tev (default)");
  sub->add_flag("--json", request->json, "Print the counts as one JSON object");
  return [=]() -> int {
    std::string over;
    BudgetRequest r = *request;
    r.out = &std::cout;
    r.first_overrun = &over;
    bool fits = false;
    if (const PathInfo* owner = path_of_program_file(*scene)) {
      fits = owner->budget_file(*scene, r);
    } else {
      const PathInfo& info = find_path(*path);
      if (!info.budget) {
        std::string with;
        for (const PathInfo& p : all_paths()) {
          if (p.budget) with += (with.empty() ? "" : ", ") + p.name;
        }
        throw InputError("--path", *path,
                         "path " + info.name + " has no budget (paths with one: " + with + ")");
      }
      fits = info.budget(load_scene(*scene), r);
    }
    std::cout.flush();
    if (!fits) throw CheckFailed("budget: " + over);
    return 0;
  };
}

}  // namespace lt::cli
