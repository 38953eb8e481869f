// A number as people read it in reports and messages: fixed-point with `precision` decimals
// ("4.00"), and an optional unit.
#pragma once

#include <cstdio>
#include <string>

namespace lt {

inline std::string fixed(double v, int precision, const char* unit = "") {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f%s", precision, v, unit);
  return buf;
}

}  // namespace lt
