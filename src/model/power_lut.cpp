#include "model/power_lut.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "model/translucency.h"

namespace lt::model {

const char* to_string(LutFormat f) {
  switch (f) {
    case LutFormat::U8:
      return "u8";
    case LutFormat::F16:
      return "f16";
    case LutFormat::F32:
      return "f32";
  }
  return "?";
}

namespace {

// Round to the nearest IEEE half (ties to even, like a GL float->half upload). Values here are in
// [0, 1], so no overflow; below 2^-14 the spacing is the denormal step 2^-24 (kept, not flushed:
// t^p for large p lives there and a flush would make the tail of the lobe a step).
double round_to_half(double v) {
  if (v <= 0) return 0;
  int e = 0;
  std::frexp(v, &e);  // v = m * 2^e, m in [0.5, 1): the leading bit is 2^(e-1)
  const int exponent = std::max(e - 1, -14);
  const double step = std::ldexp(1.0, exponent - 10);  // 10 fraction bits
  return std::nearbyint(v / step) * step;
}

double quantise(double v, LutFormat f) {
  switch (f) {
    case LutFormat::U8:
      return std::round(v * 255.0) / 255.0;  // what GL_R8 stores and returns
    case LutFormat::F16:
      return round_to_half(v);
    case LutFormat::F32:
      return static_cast<float>(v);
  }
  return v;
}

}  // namespace

PowerLut PowerLut::build(int size, LutFormat format, std::vector<double> powers) {
  LT_CHECK(size >= 2, "a power LUT needs at least 2 texels");
  PowerLut lut;
  lut.size = size;
  lut.format = format;
  lut.powers = std::move(powers);
  lut.texels.reserve(lut.powers.size() * static_cast<size_t>(size));
  for (double p : lut.powers) {
    for (int i = 0; i < size; ++i) {
      // t_i = i / (N - 1): both ends are exact texels (t = 0 gives 0, or 1 for p = 0; t = 1 gives
      // 1).
      const double t = static_cast<double>(i) / (size - 1);
      lut.texels.push_back(static_cast<float>(quantise(lobe(t, p), format)));
    }
  }
  return lut;
}

double PowerLut::sample_linear(int row, double t) const {
  // GL_LINEAR with CLAMP_TO_EDGE at u = coordinate(t): the texel-space position is
  // u * N - 0.5 = t * (N - 1), computed directly so texel positions are exact in double.
  const double x = std::clamp(t, 0.0, 1.0) * (size - 1);
  const int i0 = std::min(static_cast<int>(std::floor(x)), size - 2);
  const double f = x - i0;
  return (1 - f) * texel(row, i0) + f * texel(row, i0 + 1);
}

}  // namespace lt::model
