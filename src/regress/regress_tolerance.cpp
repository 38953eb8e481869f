#include "regress/regress_tolerance.h"

#include "core/error.h"

namespace lt {

namespace {

void apply(const ToleranceOverride& o, Tolerance& t) {
  if (o.fail_lsb) t.fail_lsb = *o.fail_lsb;
  if (o.fail_percent) t.fail_percent = *o.fail_percent;
  if (o.hard_fail_lsb) t.hard_fail_lsb = *o.hard_fail_lsb;
  if (o.warn_lsb) t.warn_lsb = *o.warn_lsb;
  if (o.warn_percent) t.warn_percent = *o.warn_percent;
  if (o.hard_warn_lsb) t.hard_warn_lsb = *o.hard_warn_lsb;
  if (o.region) t.region = *o.region == "image" ? Region::kImage : Region::kCovered;
}

// The default, one for every path. Every path writes an 8-bit framebuffer, so the default follows
// from the 8 bits (piglit's rule): a pixel may differ by 1 LSB on at most 0.5 % of the image (a
// value on a half-LSB boundary rounds the other way after a Mesa or compiler change), none by more
// than 3. The CPU paths (reference, half, gx) shade over OSMesa's rasterised G-buffer, so a Mesa
// change moves them too: they take the same default. Judged over the whole image, so geometry
// that appears or vanishes fails. A case within those bounds that still differs from its golden
// at all warns (idiff's default warn threshold is any difference too): it passes, and the
// reviewer sees that the golden moved.
Tolerance default_regress_tolerance() {
  Tolerance t;
  t.fail_lsb = 1.0;
  t.fail_percent = 0.5;
  t.hard_fail_lsb = 3.0;
  t.region = Region::kImage;
  t.warn_lsb = 0.0;
  t.warn_percent = 0.0;
  return t;
}

}  // namespace

Tolerance regress_tolerance(const Scene& scene, const PathInfo& path) {
  for (const auto& entry : scene.regress.per_path) {
    try {
      find_path(entry.first);
    } catch (const InputError& e) {
      throw InputError(scene.file.string(), "regress.paths." + entry.first, e.what_only());
    }
  }
  Tolerance t = default_regress_tolerance();
  apply(scene.regress.every_path, t);
  if (auto it = scene.regress.per_path.find(path.name); it != scene.regress.per_path.end())
    apply(it->second, t);
  return t;
}

}  // namespace lt
