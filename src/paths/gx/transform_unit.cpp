#include "paths/gx/transform_unit.h"

#include <cmath>

namespace lt::gx {

namespace {
constexpr float kZMax = 16777215.0f;  // 2^24 - 1 [OGC gx.c GX_SetViewportJitter Zfactor]
}  // namespace

ViewTransform view_transform(const glm::mat3& r, const Camera& cam, fifo::FrameSize size) {
  ViewTransform t;
  // glm is column-major: row i of the rotation is (r[0][i], r[1][i], r[2][i]).
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) t.position[static_cast<size_t>(4 * i + j)] = r[j][i];
    t.position[static_cast<size_t>(4 * i + 3)] = 0.0f;
  }
  const double aspect = static_cast<double>(size.width) / size.height;
  const double n = cam.near, f = cam.far;
  if (cam.projection == Camera::Projection::Perspective) {
    const double tn = std::tan(glm::radians(cam.fov_y_deg) / 2);
    t.projection = {static_cast<float>(1 / (aspect * tn)),
                    0.0f,
                    static_cast<float>(1 / tn),
                    0.0f,
                    static_cast<float>(-n / (f - n)),
                    static_cast<float>(-f * n / (f - n))};
  } else {
    const double h = cam.height / 2, w = h * aspect;
    t.projection = {static_cast<float>(1 / w),        0.0f,
                    static_cast<float>(1 / h),        0.0f,
                    static_cast<float>(-1 / (f - n)), static_cast<float>(-f / (f - n))};
    t.orthographic = true;
  }
  const float w = static_cast<float>(size.width), h = static_cast<float>(size.height);
  const float offset = static_cast<float>(fifo::kScreenOffset);
  t.viewport = {w * 0.5f, -h * 0.5f, kZMax, w * 0.5f + offset, h * 0.5f + offset, kZMax};
  return t;
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
