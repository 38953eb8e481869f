#include "model/texture_sampling.h"

#include <algorithm>
#include <cmath>

namespace lt::model {

namespace {

// A texel index wrapped into [0, size - 1] by REPEAT (modulo) or MIRRORED_REPEAT (period 2 size).
int wrap_index(long long i, int size, Wrap wrap) {
  // Inside the texture both wraps leave the index as it is: the common case (a coordinate in
  // [0, 1]), which so skips the two 64-bit divisions below (most of a map sample's time).
  if (i >= 0 && i < size) return static_cast<int>(i);
  const long long period = wrap == Wrap::Repeat ? size : 2LL * size;
  long long m = i % period;
  if (m < 0) m += period;
  return static_cast<int>(m < size ? m : period - 1 - m);
}

// One axis: the lower texel, the upper one and the upper one's weight.
void axis_taps(double coordinate, int size, Wrap wrap, int& i0, int& i1, double& f) {
  double x = coordinate * size - 0.5;
  if (wrap == Wrap::ClampToEdge || !std::isfinite(x) || std::abs(x) > 1e15) {
    // Clamped to the edges (also NaN, and coordinates too large for a texel index).
    if (!(x > 0)) x = 0;
    x = std::min(x, static_cast<double>(size - 1));
    i0 = static_cast<int>(std::floor(x));
    i1 = std::min(i0 + 1, size - 1);
    f = x - i0;
    return;
  }
  const double lower = std::floor(x);
  f = x - lower;
  i0 = wrap_index(static_cast<long long>(lower), size, wrap);
  i1 = wrap_index(static_cast<long long>(lower) + 1, size, wrap);
}

}  // namespace

const char* wrap_name(Wrap wrap) {
  switch (wrap) {
    case Wrap::Repeat:
      return "REPEAT";
    case Wrap::MirroredRepeat:
      return "MIRRORED_REPEAT";
    case Wrap::ClampToEdge:
      break;
  }
  return "CLAMP_TO_EDGE";
}

BilinearTaps bilinear_taps(int width, int height, glm::dvec2 uv, Wrap wrap_s, Wrap wrap_t) {
  BilinearTaps t;
  axis_taps(uv.x, width, wrap_s, t.x0, t.x1, t.fx);
  axis_taps(uv.y, height, wrap_t, t.y0, t.y1, t.fy);
  return t;
}

glm::dvec3 sample_bilinear(const Texture& texture, glm::dvec2 uv) {
  const BilinearTaps t =
      bilinear_taps(texture.width, texture.height, uv, texture.wrap_s, texture.wrap_t);
  const glm::dvec3 bottom =
      (1 - t.fx) * texture.texel(t.x0, t.y0) + t.fx * texture.texel(t.x1, t.y0);
  const glm::dvec3 top = (1 - t.fx) * texture.texel(t.x0, t.y1) + t.fx * texture.texel(t.x1, t.y1);
  return (1 - t.fy) * bottom + t.fy * top;
}

glm::dvec3 sample_ramp(const Texture& ramp, double t) {
  return sample_bilinear(ramp, {t, 0.5});
}

}  // namespace lt::model
