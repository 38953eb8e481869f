// What a regress run is made of, read and checked before the first render: the scene files, the
// scenes and every shard's cases. Every run (in this process or in workers) starts here.
#pragma once

#include <filesystem>
#include <vector>

#include "regress/regress.h"

namespace lt {

struct RegressPlan {
  std::vector<std::filesystem::path> scene_files;
  std::vector<Scene> scenes;
  std::vector<RegressCase> cases;  // every shard's
};

// Reads and checks every input (regress.h run_regress says which); throws InputError.
RegressPlan make_regress_plan(const RegressOptions& options);

// Checks an output file before any work: its directory exists (or is `report_dir`, which -o
// creates) and it is none of `inputs`. Throws InputError naming it.
void check_output_file(const std::filesystem::path& file,
                       const std::vector<std::filesystem::path>& inputs,
                       const std::filesystem::path& report_dir);

// Creates `dir` and its parents; InputError naming it when that fails.
void make_directory(const std::filesystem::path& dir);

}  // namespace lt
