#pragma once
#include "paths/path.h"

namespace lt {
// The ground truth: a float G-buffer rasterised through OSMesa, shaded per pixel in double on the
// CPU (model::shade) on every core.
const PathInfo& reference_path_info();
}  // namespace lt
