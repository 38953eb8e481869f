#include "gx/transform_unit.h"

#include <cmath>

namespace lt::gx {

namespace {
constexpr float kZMax = 16777215.0f;  // 2^24 - 1 [OGC gx.c GX_SetViewportJitter Zfactor]
}  // namespace

Viewport frame_viewport(FrameSize size) {
  const float w = static_cast<float>(size.width), h = static_cast<float>(size.height);
  const float offset = static_cast<float>(kScreenOffset);
  return {w * 0.5f, -h * 0.5f, kZMax, w * 0.5f + offset, h * 0.5f + offset, kZMax};
}

glm::vec4 clip_position(const ViewTransform& t, const glm::vec3& p) {
  // Every product and sum is its own float operation, left to right: what Dolphin's x86-64 build
  // computes (no FMA: the core is compiled with -ffp-contract=off, CMakeLists.txt).
  const auto& m = t.position;
  const float x = m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3];
  const float y = m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7];
  const float z = m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11];
  const auto& q = t.projection;
  if (t.orthographic) return {q[0] * x + q[1], q[2] * y + q[3], q[4] * z + q[5], 1.0f};
  // "result.z = (proj[4] * vec.z + proj[5]) * (1.0f - (float)1e-7)" [DSW MultipleVec3Perspective]:
  // Dolphin's nudge of z off the far plane.
  constexpr float kNudge = 1.0f - static_cast<float>(1e-7);
  return {q[0] * x + q[1] * z, q[2] * y + q[3] * z, (q[4] * z + q[5]) * kNudge, -z};
}

}  // namespace lt::gx
