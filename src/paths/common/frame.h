// What the GL paths share around a frame: the start (viewport, clear, depth, matrices) and the
// read-back of the 8-bit framebuffer as the path result.
#pragma once

#include "paths/path.h"

namespace lt {

// The start every GL path shares: viewport, clear to the scene's background with alpha 0 (alpha
// is coverage), depth test on, the shared matrices loaded.
void begin_frame(const PathContext& ctx);

// Additive passes after the first (arbfp under --profile, the combiners' one light a pass): ONE,
// ONE blending, depth EQUAL against the first pass's depth, no depth writes. The 8-bit
// framebuffer clamps the sum at 1 (lossless: every term is >= 0) and rounds each pass before it
// is added. The one known loss of EQUAL: where two faces meet at a vertex and their depths tie
// in 24 bits at a pixel, both pass and the pixel gets the pass twice (the reference's single
// pass keeps one fragment); a stencil "first fragment only" would fix it, and the OSMesa context
// has no stencil buffer (seen on one corner pixel of thin_vs_thick).
void begin_additive_passes();
// Back to the first pass's state: no blending, depth LESS with writes.
void end_additive_passes();

// Reads the 8-bit OSMesa colour buffer as the path result (flips to top row first, A = coverage).
Image read_framebuffer(const gl::Context& gl);

}  // namespace lt
