#include "model/texture_sampling.h"

#include <algorithm>
#include <cmath>

namespace lt::model {

namespace {

// One axis: the lower texel, the upper one and the upper one's weight, clamped to the edges.
void axis_taps(double coordinate, int size, int& i0, int& i1, double& f) {
  double x = coordinate * size - 0.5;
  if (!(x > 0)) x = 0;  // also NaN
  x = std::min(x, static_cast<double>(size - 1));
  i0 = static_cast<int>(std::floor(x));
  i1 = std::min(i0 + 1, size - 1);
  f = x - i0;
}

}  // namespace

BilinearTaps bilinear_taps(int width, int height, glm::dvec2 uv) {
  BilinearTaps t;
  axis_taps(uv.x, width, t.x0, t.x1, t.fx);
  axis_taps(uv.y, height, t.y0, t.y1, t.fy);
  return t;
}

glm::dvec3 sample_bilinear(const Texture& texture, glm::dvec2 uv) {
  const BilinearTaps t = bilinear_taps(texture.width, texture.height, uv);
  const glm::dvec3 bottom =
      (1 - t.fx) * texture.texel(t.x0, t.y0) + t.fx * texture.texel(t.x1, t.y0);
  const glm::dvec3 top = (1 - t.fx) * texture.texel(t.x0, t.y1) + t.fx * texture.texel(t.x1, t.y1);
  return (1 - t.fy) * bottom + t.fy * top;
}

glm::dvec3 sample_ramp(const Texture& ramp, double t) {
  return sample_bilinear(ramp, {t, 0.5});
}

}  // namespace lt::model
