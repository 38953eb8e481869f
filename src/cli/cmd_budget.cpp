#include <iostream>
#include <map>

#include "budget/report.h"
#include "cli/commands.h"
#include "cli/lights_option.h"
#include "core/error.h"
#include "core/fs.h"
#include "load/load_scene.h"
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
  for (const PathInfo& p : all_paths()) {
    if (p.reads_program_text(text)) return &p;
  }
  return nullptr;
}

// "arbfp: ps_2_0, ps_2_x, ...; combiners: gl13-2units, ...; gx: wii-tev": every budget's
// profiles, by the path that owns them.
std::string profiles_by_path() {
  std::string out;
  for (const PathInfo& p : all_paths()) {
    if (p.budget_profiles.empty()) continue;
    std::string names;
    for (const std::string& n : p.budget_profiles) names += (names.empty() ? "" : ", ") + n;
    out += (out.empty() ? "" : "; ") + p.name + ": " + names;
  }
  return out;
}

// Each --profile given to the path that has it: at most one per path (the arbfp one checks
// fragment and vertex programs, through its partner).
std::map<std::string, std::string> profiles_per_path(const std::vector<std::string>& given) {
  std::map<std::string, std::string> out;
  for (const std::string& name : given) {
    const PathInfo* owner = nullptr;
    for (const PathInfo& p : all_paths()) {
      for (const std::string& n : p.budget_profiles) {
        if (n == name) owner = &p;
      }
    }
    if (!owner) {
      throw InputError("--profile", name, "unknown profile (" + profiles_by_path() + ")");
    }
    const auto [it, added] = out.emplace(owner->name, name);
    if (!added) {
      throw InputError("--profile", name,
                       "a second " + owner->name + " profile (" + it->second +
                           " is given too): one profile per kind of input");
    }
  }
  return out;
}

// The path that counts a scene: --path, which must have a budget.
const PathInfo& scene_path(const std::string& path) {
  const PathInfo& info = find_path(path);
  if (info.budget_profiles.empty()) {
    std::string with;
    for (const PathInfo& p : all_paths()) {
      if (!p.budget_profiles.empty()) with += (with.empty() ? "" : ", ") + p.name;
    }
    throw InputError("--path", path,
                     "path " + info.name + " has no budget (paths with one: " + with + ")");
  }
  return info;
}

struct Input {
  std::string file;
  const PathInfo* program_path = nullptr;  // the program file's path; nullptr for a scene
  bool readable = true;                    // false: its error is reported in its turn
};

}  // namespace

// `ltrender budget FILE... [--path P] [--variant V] [--profile NAME]... [--json]`: for a scene,
// what path P builds for it, counted against P's profile; for a program file, the file itself,
// counted by the path whose files end that way (or start with its header) against that path's
// profile. Each path owns its counter and profiles (PathInfo::budget, budget_file); all fill the
// one report (budget/report.h) this command prints. Options that cannot apply to the
// inputs are refused before anything is counted. Every file is checked; then exit 2 if one was
// not valid (each named on its own line, and a JSON error record each with --json), else 1 if
// one is over, naming the file and the limit.
Action add_budget(CLI::App& app) {
  auto* sub = app.add_subcommand("budget", "Check program/stage budgets against hardware profiles");
  auto files = std::make_shared<std::vector<std::string>>();
  auto path = std::make_shared<std::string>(default_budget_path().name);
  auto variant = std::make_shared<std::string>();
  auto profiles = std::make_shared<std::vector<std::string>>();
  auto json = std::make_shared<bool>(false);
  auto scene_options = std::make_shared<SceneOptions>();
  sub->add_option("FILE", *files,
                  "Scene files, or program files: .fp/.vp/.arb or !!ARBfp1.0/!!ARBvp1.0 text (ARB "
                  "programs), .asm/.vsh/.psh or vs_2_0/ps_2_0/... text (D3D9 assembly), .comb (GL "
                  "1.3 combiner programs), .c/.gx (GX programs)")
      ->required();
  CLI::Option* path_option =
      sub->add_option("--path", *path,
                      "For scenes: arbfp (programs, the default), combiners (GL stages, units, "
                      "passes) or gx (TEV stages, texgens, channels, lights, passes). Given, every "
                      "program file must be that path's");
  sub->add_option("--variant", *variant, "Path variant (default: the path's default)");
  sub->add_option(
         "--profile", *profiles,
         "One per kind of input, repeated or comma-separated; each goes to the path that "
         "has it. arbfp: ps_2_0 (default), ps_2_x, ps_2_a, ps_2_b, ps_3_0, arbfp1-min, "
         "vs_1_1, vs_2_0, vs_3_0, arbvp1-min (a D3D9 program's default is its version's; the "
         "partner profile checks the other program kind); combiners: gl13-2units "
         "(default), gl13-3units, gl-8units; gx: wii-tev (default)")
      ->delimiter(',');
  sub->add_flag("--json", *json,
                "Print one ltrender-budget-2 JSON object per file, an error record for an "
                "invalid one (docs/budget.md)");
  add_lights_option(sub, *scene_options);
  return [=]() -> int {
    const std::map<std::string, std::string> chosen = profiles_per_path(*profiles);
    const bool path_given = path_option->count() > 0;
    const PathInfo* scenes_by = path_given ? &scene_path(*path) : nullptr;
    // Which path counts each input, known before anything is counted: a file that cannot be
    // read is reported in its turn.
    std::vector<Input> inputs;
    for (const std::string& file : *files) {
      Input in{file};
      try {
        in.program_path = path_of_program_file(file);
      } catch (const InputError&) {
        in.readable = false;
      }
      inputs.push_back(in);
    }
    std::map<std::string, std::string> counted_by;  // path -> the first input it counts
    for (const Input& in : inputs) {
      if (!in.readable) continue;
      if (in.program_path && path_given && in.program_path->name != *path) {
        throw InputError(
            in.file, "--path",
            "a program file of " + in.program_path->name + ", which counts it; --path " + *path +
                " counts scenes (leave --path out, or name " + in.program_path->name + ")");
      }
      const std::string by =
          in.program_path ? in.program_path->name : (scenes_by ? scenes_by->name : *path);
      counted_by.emplace(by, in.file);
    }
    for (const auto& [owner, profile] : chosen) {
      if (counted_by.count(owner)) continue;
      std::string inputs_by;
      for (const auto& [by, file] : counted_by) {
        inputs_by += (inputs_by.empty() ? "" : ", ") + file + ": " + by;
      }
      throw InputError("--profile", profile,
                       "a profile of " + owner + ", which counts none of the inputs" +
                           (inputs_by.empty() ? "" : " (" + inputs_by + ")"));
    }
    auto profile_of = [&chosen](const PathInfo& p) {
      const auto it = chosen.find(p.name);
      return it == chosen.end() ? std::string() : it->second;
    };

    std::string over;
    std::vector<InputError> invalid;
    for (const Input& in : inputs) {
      try {
        budget::Report report;
        if (!in.readable) {
          (void)path_of_program_file(in.file);  // throws the file's own error
        } else if (in.program_path) {
          report = in.program_path->budget_file(in.file, profile_of(*in.program_path));
        } else {
          const PathInfo& p = scenes_by ? *scenes_by : scene_path(*path);
          report = p.budget(load_scene(in.file, *scene_options), *variant, profile_of(p));
        }
        std::cout << (*json ? budget::to_json(report) + "\n" : budget::to_text(report));
        if (!report.fits() && over.empty()) over = report.first_overrun();
      } catch (const InputError& e) {
        if (*json) std::cout << budget::error_json(in.file, e) << "\n";
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
