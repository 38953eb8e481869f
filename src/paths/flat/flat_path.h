#pragma once
#include "paths/path.h"

namespace lt {
// The timing baseline: the same geometry, same transform and depth test, one constant colour
// per material (its albedo) through fixed-function state. path/flat is the technique's cost.
const PathInfo& flat_path_info();
}  // namespace lt
