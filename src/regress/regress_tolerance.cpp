#include "regress/regress_tolerance.h"

#include "core/error.h"

namespace lt {

namespace {

void apply(const ToleranceOverride& o, Tolerance& t) {
  if (o.fail_lsb) t.fail_lsb = *o.fail_lsb;
  if (o.fail_percent) t.fail_percent = *o.fail_percent;
  if (o.hard_fail_lsb) t.hard_fail_lsb = *o.hard_fail_lsb;
  if (o.region) t.region = *o.region == "image" ? Region::kImage : Region::kCovered;
}

}  // namespace

Tolerance default_regress_tolerance(const PathInfo&) {
  Tolerance t;
  t.fail_lsb = 1.0;
  t.fail_percent = 0.5;
  t.hard_fail_lsb = 3.0;
  t.region = Region::kImage;
  return t;
}

Tolerance regress_tolerance(const Scene& scene, const PathInfo& path) {
  for (const auto& entry : scene.regress.per_path) {
    try {
      find_path(entry.first);
    } catch (const InputError& e) {
      throw InputError(scene.file.string(), "regress.paths." + entry.first, e.what_only());
    }
  }
  Tolerance t = default_regress_tolerance(path);
  apply(scene.regress.every_path, t);
  if (auto it = scene.regress.per_path.find(path.name); it != scene.regress.per_path.end())
    apply(it->second, t);
  return t;
}

}  // namespace lt
