// `--threads N`, the option of the commands that render with the CPU paths (render, regress,
// advise): how many threads their per-pixel stages (reference, half, gx) use. Default: every
// core this process may use (core/cpu_affinity.h); the bench has its own `--cpu-threads`, one
// when pinned to a core, for figures that repeat.
#pragma once

#include <CLI/CLI.hpp>

namespace lt::cli {

void add_threads_option(CLI::App* command);

}  // namespace lt::cli
