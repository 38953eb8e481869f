#include "advise/variant_trials.h"

#include <utility>

#include "advise/material_error.h"
#include "render/evaluate.h"

namespace lt::advise {

VariantTrials::VariantTrials(const Scene& scene, const PathInfo& path, const PathOptions& options,
                             std::string profile, int width, int height)
    : scene_(scene),
      path_(path),
      options_(options),
      profile_(std::move(profile)),
      session_(scene, width, height),
      reference_(render_reference(session_)),
      material_of_pixel_(material_per_pixel(session_.context())) {}

const VariantTrials::Trial& VariantTrials::trial(
    const std::string& variant, const std::function<std::string(const budget::Report&)>& unfit) {
  if (auto it = trials_.find(variant); it != trials_.end()) return it->second;
  Trial t;
  if (std::string refused = path_.refusal(scene_, variant); !refused.empty()) {
    t.failed = refused;
  } else {
    t.budget = path_.budget(scene_, variant, profile_);
    if (unfit) t.failed = unfit(t.budget);
    if (t.failed.empty()) {
      auto built = session_.build(path_, variant, options_);
      built->frame();
      t.image = built->result();
      t.encoding = test_encoding(*built);
    }
  }
  return trials_.emplace(variant, std::move(t)).first->second;
}

Comparison VariantTrials::compare(const Trial& t, size_t material) const {
  return compare_material(t.image, reference_, t.encoding, material_of_pixel_,
                          static_cast<int>(material));
}

}  // namespace lt::advise
