// `ltrender regress merge SHARD.json...`: the shards of one run (each `regress --shard I/N
// --json`) made one review: one JSON, one JUnit and one page, identical (times aside) to what the
// run without shards writes. Every shard of the run must be there exactly once, each complete,
// and all of one run (the same scenes, paths, size and goldens); anything else is refused by name.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "regress/regress.h"

namespace lt {

struct MergeOptions {
  std::vector<std::filesystem::path> shards;                // SHARD.json files
  std::filesystem::path junit_file, json_file, report_dir;  // empty: not written
  std::optional<std::string> label;                         // --label; none: the shards' own
};

// Reads and checks every shard (InputError naming the file, or the option, before anything is
// written), writes what the options name and returns the merged run; `as_run` gets the options
// a run without shards would have had (its goldens, label and outputs).
RegressRun merge_regress_shards(const MergeOptions& options, RegressOptions& as_run);

// Checks a name given on the command line that goes into file names or class names (--label,
// --golden-key): letters, digits, '.', '-' and '_', not empty, not "." or "..".
void check_name_option(const std::string& option, const std::string& value);

}  // namespace lt
