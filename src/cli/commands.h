// Each subcommand lives in its own file (cmd_<name>.cpp): it registers its options on the app
// and returns the action to run when it is chosen. main.cpp only parses and dispatches.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace lt::cli {

// Returns the exit code: 0 success, 1 a check failed. Bad input throws lt::InputError (exit 2).
using Action = std::function<int()>;

Action add_render(CLI::App& app);
Action add_compare(CLI::App& app);
Action add_bake(CLI::App& app);
Action add_budget(CLI::App& app);
Action add_bench(CLI::App& app);
Action add_info(CLI::App& app);
Action add_meshgen(CLI::App& app);
Action add_export(CLI::App& app);
Action add_regress(CLI::App& app);

}  // namespace lt::cli
