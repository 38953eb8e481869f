// Each port's error bound against the ground truth: one table, src/paths/bounds/path_bounds.json
// (embedded in the binary), a row per path, variant and scene (a demo scene's stem, or "*" for
// any scene without a row of its own), measured with `ltrender bench` over the demo scenes and
// set with a margin, each with the reason the error is what it is. tests/bounds_test.cpp holds
// every demo scene to its row; `regress --update` holds a new golden to its path's "*" row
// before writing it (docs/regress.md "A new golden"), since a recorded image is not yet a
// reference.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "metrics/compare.h"

namespace lt {

struct PathBound {
  std::string path, variant, scene;  // scene: a stem ("backlit_sphere") or "*"
  double max_lsb = 0, mean_lsb = 0;  // over the covered pixels
  std::optional<double> p99_lsb, image_max_lsb, min_mean_lsb;
  std::string reason;
};

// The table, parsed once.
const std::vector<PathBound>& path_bounds();

// The row for a scene: its own row wins over the path's "*" row; null when neither exists.
const PathBound* find_path_bound(const std::string& path, const std::string& variant,
                                 const std::string& scene);

// The path's "*" row: what holds for a scene the table was not measured on. Null for a variant
// whose error depends on the scene (every gx variant and three of combiners': their rows are
// per demo scene only).
const PathBound* general_path_bound(const std::string& path, const std::string& variant);

// What `c` (a render against the ground truth: covered and whole-image figures) breaks of `b`'s
// per-pixel bounds (covered max and p99, whole-image max), one line each ("covered max 3.20 LSB
// over the bound's 1.00"); empty within them. These hold for a scene the row was not measured
// on; its means do not (a small image, or one mostly lit, has another mean rounding error).
std::vector<std::string> pixel_bound_violations(const PathBound& b, const Comparison& c);
// Those and the means: the covered mean's bound, and min_mean (the variant really is another
// curve: a lower bound), which hold on the scenes the row was measured on.
std::vector<std::string> bound_violations(const PathBound& b, const Comparison& c);

}  // namespace lt
