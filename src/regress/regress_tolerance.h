// How far a render may move from its golden before `ltrender regress` fails it: the path's
// default, then the scene's "regress" block (every path, then the path's own entry).
#pragma once

#include "metrics/compare.h"
#include "paths/path.h"
#include "scene/scene.h"

namespace lt {

// The default with the scene's overrides applied. Throws InputError naming the scene file and
// the key (regress.paths.NAME) for a path name the registry does not know.
Tolerance regress_tolerance(const Scene& scene, const PathInfo& path);

}  // namespace lt
