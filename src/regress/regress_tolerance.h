// How far a render may move from its golden before `ltrender regress` fails it: the path's
// default, then the scene's "regress" block (every path, then the path's own entry).
#pragma once

#include "metrics/compare.h"
#include "paths/path.h"
#include "scene/scene.h"

namespace lt {

// The default of a path. Every path writes an 8-bit framebuffer, so every default follows from
// the 8 bits (piglit's rule): a pixel may differ by 1 LSB on at most 0.5 % of the image (a value
// on a half-LSB boundary rounds the other way after a Mesa or compiler change), none by more than
// 3. The CPU paths (reference, half, gx) shade over OSMesa's rasterised G-buffer, so a Mesa
// change moves them too: they take the same default. Judged over the whole image, so geometry
// that appears or vanishes fails.
Tolerance default_regress_tolerance(const PathInfo& path);

// The default with the scene's overrides applied. Throws InputError naming the scene file and
// the key (regress.paths.NAME) for a path name the registry does not know.
Tolerance regress_tolerance(const Scene& scene, const PathInfo& path);

}  // namespace lt
