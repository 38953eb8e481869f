// The one evaluate step (render a path, the reference, the comparison) that bench, regress,
// export and advise share: a path's frame in a session, the ground truth of the session's scene,
// and a frame compared with the reference (as `compare` does) or with a golden (as `regress`
// does).
#pragma once

#include <string>

#include "image/image.h"
#include "metrics/compare.h"
#include "paths/path.h"
#include "render/session.h"

namespace lt {

// One frame of `path` with `variant` (resolved) in this session: built, drawn, read back.
Image render_frame(RenderSession& session, const PathInfo& path, const std::string& variant,
                   const PathOptions& options = {});

// One frame of the ground-truth path (the reference) in this session: float RGBA, alpha the
// coverage every comparison's "covered" region is taken from.
Image render_reference(RenderSession& session);

// How a path's images are compared: a float path unquantised, an 8-bit one as its bytes.
TestEncoding test_encoding(const Path& path);

// The error of `path`'s last frame (frame() already run) against `reference`.
Comparison compare_with_reference(Path& path, const Image& reference);
// The same for a frame already read back (`render`, encoded as test_encoding(path) says): a GL
// path's result() reads the framebuffer, which another path drawn since (the reference's
// G-buffer) has overwritten.
Comparison compare_with_reference(const Image& render, TestEncoding encoding,
                                  const Image& reference);

// The error of `render` against `golden`, an image of the same size read from an 8-bit file:
// both compared as their bytes (the render as the 8-bit image it would be written as). A PNG
// golden carries no coverage, so the render's is taken: region "covered" then judges the
// pixels the scene draws.
Comparison compare_with_golden(const Image& render, Image golden);

}  // namespace lt
