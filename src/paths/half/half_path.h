#pragma once
#include "paths/path.h"

namespace lt {
// The seed's `half` arithmetic emulated on the CPU: the reference's float G-buffer, every pixel
// shaded with every intermediate rounded to IEEE binary16 (what fp16 hardware does to the term).
const PathInfo& half_path_info();
}  // namespace lt
