// What the GL paths share around a frame: the start (viewport, clear, depth, matrices) and the
// read-back of the 8-bit framebuffer as the path result.
#pragma once

#include "paths/path.h"

namespace lt {

// The start every GL path shares: viewport, clear to the scene's background with alpha 0 (alpha
// is coverage), depth test on, the shared matrices loaded.
void begin_frame(const PathContext& ctx);

// Reads the 8-bit OSMesa colour buffer as the path result (flips to top row first, A = coverage).
Image read_framebuffer(const gl::Context& gl);

}  // namespace lt
