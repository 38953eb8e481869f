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

glm::vec3 eye_position(const std::array<float, 12>& m, const glm::vec3& p) {
  // Every product and sum is its own float operation, left to right: what Dolphin's x86-64 build
  // computes (no FMA: the core is compiled with -ffp-contract=off, CMakeLists.txt).
  return {m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
          m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]};
}

glm::vec3 eye_normal(const std::array<float, 9>& m, const glm::vec3& n) {
  return {m[0] * n.x + m[1] * n.y + m[2] * n.z, m[3] * n.x + m[4] * n.y + m[5] * n.z,
          m[6] * n.x + m[7] * n.y + m[8] * n.z};
}

glm::vec4 clip_position(const ViewTransform& t, const glm::vec3& p) {
  const glm::vec3 eye = eye_position(t.position, p);
  const float x = eye.x, y = eye.y, z = eye.z;
  const auto& q = t.projection;
  if (t.orthographic) return {q[0] * x + q[1], q[2] * y + q[3], q[4] * z + q[5], 1.0f};
  // "result.z = (proj[4] * vec.z + proj[5]) * (1.0f - (float)1e-7)" [DSW MultipleVec3Perspective]:
  // Dolphin's nudge of z off the far plane.
  constexpr float kNudge = 1.0f - static_cast<float>(1e-7);
  return {q[0] * x + q[1] * z, q[2] * y + q[3] * z, (q[4] * z + q[5]) * kNudge, -z};
}

}  // namespace lt::gx
