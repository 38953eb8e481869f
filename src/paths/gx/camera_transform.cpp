#include "paths/gx/camera_transform.h"

#include <cmath>

namespace lt::gx {

ViewTransform view_transform(const glm::mat3& r, const Camera& cam, FrameSize size) {
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
  t.viewport = frame_viewport(size);
  return t;
}

}  // namespace lt::gx
