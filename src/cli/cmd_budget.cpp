#include <iostream>

#include "cli/commands.h"
#include "cli/lights_option.h"
#include "core/error.h"
#include "core/fs.h"
#include "paths/path.h"

namespace lt::cli {

namespace {

// The path whose program files `file` is: by extension, else (not a scene) by the header its
// text starts with; nullptr for a scene.
const PathInfo* path_of_program_file(const std::string& file) {
  const std::string ext = fs::path(file).extension().string();
  for (const PathInfo& p : all_paths()) {
    for (const std::string& e : p.program_extensions) {
      if (e == ext) return &p;
    }
  }
  if (ext == ".json") return nullptr;
  const std::string text = read_text_file(file);
  const size_t start = text.find_first_not_of(" \t\r\n");
  for (const PathInfo& p : all_paths()) {
    for (const std::string& h : p.program_headers) {
      if (start != std::string::npos && text.compare(start, h.size(), h) == 0) return &p;
    }
  }
  return nullptr;
}

// One file's budget; true when it fits.
bool budget_one(const std::string& file, const std::string& path, const SceneOptions& scene_options,
                BudgetRequest r) {
  if (const PathInfo* owner = path_of_program_file(file)) return owner->budget_file(file, r);
  const PathInfo& info = find_path(path);
  if (!info.budget) {
    std::string with;
    for (const PathInfo& p : all_paths()) {
      if (p.budget) with += (with.empty() ? "" : ", ") + p.name;
    }
    throw InputError("--path", path,
                     "path " + info.name + " has no budget (paths with one: " + with + ")");
  }
  return info.budget(load_scene(file, scene_options), r);
}

}  // namespace

// `ltrender budget FILE... [--path P] [--variant V] [--profile NAME] [--json]`: for a scene, what
// path P builds for it, counted against the profile; for a program file, the file itself,
// counted by the path whose files end that way (or start with its header). Each path owns its
// counter and profiles (PathInfo::budget, budget_file). Every file is checked; then exit 2 if
// one was not valid (each named on its own line), else 1 if one is over, naming the limit.
Action add_budget(CLI::App& app) {
  auto* sub = app.add_subcommand("budget", "Check program/stage budgets against hardware profiles");
  auto files = std::make_shared<std::vector<std::string>>();
  auto path = std::make_shared<std::string>("arbfp");
  auto request = std::make_shared<BudgetRequest>();
  auto scene_options = std::make_shared<SceneOptions>();
  sub->add_option("FILE", *files,
                  "Scene files, or program files: .fp/.vp/.arb or !!ARBfp1.0/!!ARBvp1.0 text (ARB "
                  "programs), .c/.gx (GX programs)")
      ->required();
  sub->add_option("--path", *path,
                  "For scenes: arbfp (programs), combiners (GL stages, units, passes) or gx (TEV "
                  "stages, texgens, channels, lights, passes)");
  sub->add_option("--variant", request->variant, "Path variant (default: the path's default)");
  sub->add_option("--profile", request->profile,
                  "arbfp: ps_2_0 (default), ps_2_x, arbfp1-min, vs_2_0, arbvp1-min (the partner "
                  "profile checks the other program kind); combiners: gl13-2units (default), "
                  "gl13-3units, gl-8units; gx: wii-tev (default)");
  sub->add_flag("--json", request->json,
                "Print the counts as JSON, one object per file (docs/budget.md)");
  add_lights_option(sub, *scene_options);
  return [=]() -> int {
    std::string over;
    std::vector<InputError> invalid;
    for (const std::string& file : *files) {
      std::string first_overrun;
      BudgetRequest r = *request;
      r.out = &std::cout;
      r.first_overrun = &first_overrun;
      try {
        if (!budget_one(file, *path, *scene_options, r) && over.empty()) over = first_overrun;
      } catch (const InputError& e) {
        invalid.push_back(e);
      }
    }
    std::cout.flush();
    if (!invalid.empty()) {
      // The last one goes through main's handler like any other bad input (exit 2).
      for (size_t i = 0; i + 1 < invalid.size(); ++i) print_input_error(invalid[i].what());
      throw invalid.back();
    }
    if (!over.empty()) throw CheckFailed("budget: " + over);
    return 0;
  };
}

}  // namespace lt::cli
