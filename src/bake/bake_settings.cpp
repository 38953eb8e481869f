#include "bake/bake_settings.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace lt::bake {

void validate(const BakeSettings& s) {
  if (s.rays < 1 || s.rays > kMaxRays) {
    throw InputError(
        "--rays", "",
        "must be in [1, " + std::to_string(kMaxRays) + "], got " + std::to_string(s.rays));
  }
  if (s.max_distance && !(std::isfinite(*s.max_distance) && *s.max_distance > 0.0)) {
    throw InputError("--max-distance", "", "must be a finite number > 0");
  }
  if (!(std::isfinite(s.max_distance_relative) && s.max_distance_relative > 0.0)) {
    throw InputError("--max-distance-relative", "", "must be a finite number > 0");
  }
  if (s.threads < 0 || s.threads > 1024) {
    throw InputError("--threads", "", "must be in [0, 1024] (0: all cores)");
  }
}

void validate(const ColorMap& m) {
  auto in_unit = [](double x) { return std::isfinite(x) && x >= 0.0 && x <= 1.0; };
  if (!in_unit(m.min)) throw InputError("--min", "", "must be in [0, 1]");
  if (!in_unit(m.max)) throw InputError("--max", "", "must be in [0, 1]");
  if (m.min > m.max) {
    // Thin parts are bright (GDC 2011): an inverted map would be plain AO, not thickness.
    throw InputError("--min", "",
                     "must not exceed --max (thin parts get --max, thick parts --min)");
  }
  if (!in_unit(m.tint.x) || !in_unit(m.tint.y) || !in_unit(m.tint.z)) {
    throw InputError("--tint", "", "each of R,G,B must be in [0, 1]");
  }
}

}  // namespace lt::bake
