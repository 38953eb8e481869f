// The XF's position transform and the viewport (gx-hardware.md §2.6): what the camera loads into
// GX_PNMTX0, the projection and the viewport registers, and the clip-space position of a vertex
// computed from them in float, operation for operation as Dolphin's software renderer does
// [DSW TransformUnit.cpp TransformPosition, MultiplyVec3Mat34, MultipleVec3Perspective,
// MultipleVec3Ortho]. The FIFO encoder writes these same floats (fifo/xf_registers.h), so the
// emulator and Dolphin start every triangle from bit-identical vertices.
#pragma once

#include <array>
#include <glm/glm.hpp>

#include "gx/gx_types.h"

namespace lt::gx {

// GX_SetViewport(0, 0, w, h, 0, 1) as XF holds it: half width, minus half height (y down), the
// z range and far z in 24-bit depth units, and the origin shifted by the 342-pixel screen
// offset [OGC gx.c GX_SetViewportJitter L1767-1791] [DHW XFMemory.h Viewport].
struct Viewport {
  float wd = 0, ht = 0, z_range = 0, x_orig = 0, y_orig = 0, far_z = 0;
};

struct ViewTransform {
  std::array<float, 12> position{};   // GX_PNMTX0: 3 rows of 4 (world-to-eye rotation, no move)
  std::array<float, 6> projection{};  // GX_LoadProjectionMtx's p0..p5 [OGC gx.c L1797-1830]
  bool orthographic = false;          // GX_ORTHOGRAPHIC (1) or GX_PERSPECTIVE (0)
  Viewport viewport;
};

// GX_SetViewport(0, 0, w, h, 0, 1) for a frame of `size`: the viewport every frame uses, whatever
// its camera (paths/gx/camera_transform.h loads the camera's matrices beside it).
Viewport frame_viewport(FrameSize size);

// The eye-space position the XF computes with a 3x4 position matrix: each row's products summed
// left to right, then its fourth column [DSW TransformUnit.cpp MultiplyVec3Mat34]. The software
// renderer lights from this (its mvPosition) [DSW TransformUnit.cpp TransformColor].
glm::vec3 eye_position(const std::array<float, 12>& matrix, const glm::vec3& position);
// The eye-space normal with a 3x3 normal matrix, rows summed left to right [DSW TransformUnit.cpp
// MultiplyVec3Mat33, TransformNormal]; the lighting normalises it (xf_lighting.h).
glm::vec3 eye_normal(const std::array<float, 9>& matrix, const glm::vec3& normal);

// The clip-space (x, y, z, w) of a position as the XF computes it: the 3x4 position matrix,
// rows summed left to right, then the projection; perspective z is scaled by (1 - 1e-7) and
// w = -z_eye [DSW TransformUnit.cpp MultipleVec3Perspective]; orthographic w = 1.
glm::vec4 clip_position(const ViewTransform& transform, const glm::vec3& position);

}  // namespace lt::gx
