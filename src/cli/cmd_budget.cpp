#include <iostream>

#include "budget/budget.h"
#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/gx/gx_budget.h"

namespace lt::cli {

namespace {

bool is_gx_program_file(const std::string& path) {
  const std::string ext = fs::path(path).extension().string();
  return ext == ".c" || ext == ".gx";
}

int print_gx(const gx::GxBudgetReport& r, bool json) {
  if (json) {
    std::cout << gx::to_json(r).dump(2) << "\n";
  } else {
    std::cout << gx::to_text(r);
  }
  std::cout.flush();
  if (!r.fits()) throw CheckFailed("budget: " + r.first_overrun());
  return 0;
}

}  // namespace

// `ltrender budget SCENE [--path arbfp|combiners|gx] [--variant V] [--profile P] [--json]`:
// counts every program the path generates for the scene and checks it against the profile
// (and its partner for the other program kind). `ltrender budget FILE.c` counts a GX program
// file (gx.md §2). Exit 1 when a program is over, naming the limit.
Action add_budget(CLI::App& app) {
  auto* sub = app.add_subcommand("budget", "Check program/stage budgets against hardware profiles");
  auto scene = std::make_shared<std::string>();
  auto path = std::make_shared<std::string>("arbfp");
  auto variant = std::make_shared<std::string>();
  auto profile = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  sub->add_option("SCENE", *scene, "Scene file, or a GX program file (.c, .gx)")->required();
  sub->add_option("--path", *path,
                  "arbfp (programs), combiners (GL stages, units, passes) or gx (TEV stages, "
                  "texgens, channels, lights, passes)");
  sub->add_option("--variant", *variant, "Path variant (default: the path's default)");
  sub->add_option("--profile", *profile,
                  "arbfp: ps_2_0 (default), ps_2_x, arbfp1-min, vs_2_0, arbvp1-min (the partner "
                  "profile checks the other program kind); combiners: gl13-2units (default), "
                  "gl13-3units, gl-8units; gx: wii-tev (default)");
  sub->add_flag("--json", *json, "Print the counts as one JSON object");
  return [=]() -> int {
    if (is_gx_program_file(*scene)) {
      return print_gx(gx::gx_budget_file(*scene, profile->empty() ? "wii-tev" : *profile), *json);
    }
    const Scene s = load_scene(*scene);
    if (*path == "gx") {
      return print_gx(gx::gx_budget_scene(s, *variant, profile->empty() ? "wii-tev" : *profile),
                      *json);
    }
    if (*path == "combiners") {
      // Fixed-function hardware has stages and units, not instructions: its own counter.
      const CombinerBudgetReport r =
          combiner_budget(s, profile->empty() ? "gl13-2units" : *profile, *variant);
      std::cout << (*json ? to_json(r) + "\n" : to_text(r));
      std::cout.flush();
      if (!r.fits()) throw CheckFailed("budget: " + r.over.front());
      return 0;
    }
    const budget::BudgetReport r =
        budget::run_budget(s, *path, *variant, profile->empty() ? "ps_2_0" : *profile);
    if (*json) {
      std::cout << budget::to_json(r).dump(2) << "\n";
    } else {
      std::cout << budget::format_table(r);
    }
    std::cout.flush();
    if (!r.fits()) throw CheckFailed("budget: " + r.first_overrun());
    return 0;
  };
}

}  // namespace lt::cli
