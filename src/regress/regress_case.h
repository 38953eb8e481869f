// What `ltrender regress` renders: one case per scene x path x variant, each with the golden it
// is held to. The list is built from what the user typed (scene files or folders, --paths) in a
// fixed order, so that every run, and every shard of a CI matrix, sees the same list.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "metrics/compare.h"
#include "paths/path.h"

namespace lt {

struct RegressCase {
  std::string scene;       // the scene file's stem: the goldens are named by it
  size_t scene_index = 0;  // into the list of scene files
  const PathInfo* path = nullptr;
  std::string variant;  // canonical name
  bool default_variant = true;
  std::string skip_reason;  // non-empty: the variant cannot be exact for this scene
  Tolerance tolerance;      // regress_tolerance.h

  // "scene/path/variant": unique in a run, what JUnit, the JSON and the page call the case.
  std::string id() const;
  // SCENE__PATH.png for the path's default variant (the name ltrender's own goldens have always
  // had), SCENE__PATH__VARIANT.png for any other, with file_name_safe characters.
  std::string golden_name() const;
};

// The scene files of the inputs: a file as given, a folder as its *.json files (not its
// subfolders), sorted. Throws InputError for an input that does not exist, a folder without
// scenes, or two scenes with the same stem (their goldens would share names).
std::vector<std::filesystem::path> collect_scene_files(
    const std::vector<std::filesystem::path>& inputs);

// One entry of --paths: PATH (its default variant), PATH:VARIANT, or PATH:* (every listed
// variant, as bench runs them).
struct PathRequest {
  const PathInfo* path = nullptr;
  std::vector<std::string> variants;  // canonical names, in the path's order
};

// Parses a comma-separated --paths list; empty means every path but the timing baseline, each
// at its default variant (the set ltrender's own goldens hold). Throws InputError naming --paths.
std::vector<PathRequest> parse_path_list(const std::string& list);

// Every scene x request x variant, in scene order, then --paths order. Variants a scene cannot
// take exactly (PathInfo::refusal) are cases with a skip reason. Throws InputError for a bad
// "regress" block in a scene, or two cases whose goldens would be one file.
std::vector<RegressCase> expand_cases(const std::vector<std::filesystem::path>& scene_files,
                                      const std::vector<Scene>& scenes,
                                      const std::vector<PathRequest>& requests);

}  // namespace lt
