#pragma once
#include "paths/path.h"

namespace lt {
// Per-pixel ARB vertex + fragment programs (SM2 model), generated per material, with the pow
// variants of arb_variant.h selected by --variant.
const PathInfo& arbfp_path_info();
}  // namespace lt
