#include "cli/commands.h"
#include "core/error.h"

namespace lt::cli {

// The instruction/stage budget checker arrives with the arbfp and combiners paths (issues 4, 5).
// Until then the command exists so that `ltrender --help` is complete, and says so plainly.
Action add_budget(CLI::App& app) {
  auto* sub = app.add_subcommand("budget", "Check program/stage budgets against hardware profiles");
  auto scene = std::make_shared<std::string>();
  sub->add_option("SCENE", *scene, "Scene file")->required();
  sub->allow_extras();
  return [scene]() -> int {
    throw InputError(*scene, "", "budget: no path with a budget (arbfp, combiners) is built yet");
  };
}

}  // namespace lt::cli
