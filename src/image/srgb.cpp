#include "image/srgb.h"

#include <cmath>

namespace lt {

double srgb_to_linear(double encoded) {
  if (encoded <= 0.04045) return encoded / 12.92;
  return std::pow((encoded + 0.055) / 1.055, 2.4);
}

}  // namespace lt
