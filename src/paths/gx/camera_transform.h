// The scene's camera as the port loads it into the XF (gx-hardware.md §2.6): the position matrix
// GX_PNMTX0 and the projection a port's CPU code builds, beside the frame's viewport
// (gx/transform_unit.h frame_viewport). The emulator (gx/) takes the result as plain
// registers; only the path knows the scene's camera.
#pragma once

#include <glm/glm.hpp>

#include "gx/transform_unit.h"
#include "scene/scene.h"

namespace lt::gx {

// The scene camera at the frame's aspect (the same double-precision matrix the GL paths load,
// then float). GX clips z to [-w, 0] where GL clips to [-w, w], so the z row is GL's mapped by
// z_gx = (z_gl - w) / 2: perspective p4 = -n / (f - n), p5 = -f n / (f - n); orthographic
// p4 = -1 / (f - n), p5 = -f / (f - n) (what libogc's guPerspective / guOrtho build).
// `rotation` is the world-to-eye rotation: the scene's positions arrive camera-relative.
ViewTransform view_transform(const glm::mat3& rotation, const Camera& camera, FrameSize size);

}  // namespace lt::gx
