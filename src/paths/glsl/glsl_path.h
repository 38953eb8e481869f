#pragma once
#include "paths/path.h"

namespace lt {
// Per-pixel GLSL 1.10 with exact pow, one generated program per material.
const PathInfo& glsl_path_info();

// The generated sources for one material (exposed for tests and `info`).
struct GlslSources {
  std::string vertex, fragment;
};
GlslSources generate_glsl(const Scene& scene, const Material& material);
}  // namespace lt
