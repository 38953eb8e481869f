#pragma once
#include "paths/path.h"

namespace lt {
// Per-pixel GLSL 1.10 with exact pow, one generated program per material.
const PathInfo& glsl_path_info();
}  // namespace lt
