// bench's timing options: the named modes --quick and --precise (report/bench.h
// set_timing_mode) and the four settings a mode sets, --rounds, --min-time, --target-interval and
// --max-time. Each takes the last value given, and a mode counts as a value of all four: an
// option after the mode overrides it, one before it is overridden (`--quick --rounds 3` is three
// rounds, `--rounds 3 --quick` one). scripts/demo.sh relies on it: it names a mode and passes
// run.sh's arguments after it.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

#include "report/bench.h"

namespace lt::cli {

// Registers the options on `bench`; the returned step, run after parsing, sets `o`'s timing
// (mode, settings, and the options that overrode the mode, for the report).
std::function<void()> add_timing_options(CLI::App& bench, BenchOptions& o);

}  // namespace lt::cli
