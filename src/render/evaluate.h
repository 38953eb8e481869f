// The one evaluate step (render, reference, compare) that bench, export and advise share: the
// ground truth of a session's scene, and a path's last frame compared with it as `compare` does.
#pragma once

#include "image/image.h"
#include "metrics/compare.h"
#include "paths/path.h"
#include "render/session.h"

namespace lt {

// One frame of the ground-truth path (the reference) in this session: float RGBA, alpha the
// coverage every comparison's "covered" region is taken from.
Image render_reference(RenderSession& session);

// How a path's images are compared: a float path unquantised, an 8-bit one as its bytes.
TestEncoding test_encoding(const Path& path);

// The error of `path`'s last frame (frame() already run) against `reference`.
Comparison compare_with_reference(Path& path, const Image& reference);

}  // namespace lt
