// Each subcommand lives in its own file (cmd_<name>.cpp): it registers its options on the app
// and returns the action to run when it is chosen. main.cpp only parses and dispatches.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <functional>
#include <string>

namespace lt::cli {

// Returns the exit code: 0 success, 1 a check failed. Bad input throws lt::InputError (exit 2).
using Action = std::function<int()>;

// A number in [lo, hi]. CLI::Range lets NaN through (every comparison with it is false), and a
// NaN time or interval would leave the bench's stopping rule without an end.
inline CLI::Validator FiniteRange(double lo, double hi) {
  return CLI::Validator(
      [lo, hi](std::string& text) -> std::string {
        double v = 0;
        if (!CLI::detail::lexical_cast(text, v) || !std::isfinite(v) || v < lo || v > hi)
          return "Value " + text + " not in range " + std::to_string(lo) + " to " +
                 std::to_string(hi);
        return "";
      },
      "FLOAT in [" + std::to_string(lo) + " - " + std::to_string(hi) + "]");
}

Action add_render(CLI::App& app);
Action add_compare(CLI::App& app);
Action add_bake(CLI::App& app);
Action add_budget(CLI::App& app);
Action add_bench(CLI::App& app);
Action add_info(CLI::App& app);
Action add_meshgen(CLI::App& app);
Action add_export(CLI::App& app);
Action add_regress(CLI::App& app);
Action add_advise(CLI::App& app);
Action add_sweep(CLI::App& app);

}  // namespace lt::cli
