// The variants advise tries beside a material's pick, one axis changed (the vertex storage:
// storage_advice.h; the texture formats: texture_advice.h): each rendered once on advise's frame,
// with its budget report, and measured against the reference material by material.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "budget/report.h"
#include "image/image.h"
#include "metrics/compare.h"
#include "paths/path.h"
#include "render/session.h"
#include "scene/scene.h"

namespace lt::advise {

class VariantTrials {
 public:
  struct Trial {
    std::string failed;  // why it was not rendered: the path's refusal, or `unfit`'s reason
    budget::Report budget;
    Image image;
    TestEncoding encoding{};
  };

  VariantTrials(const Scene& scene, const PathInfo& path, const PathOptions& options,
                std::string profile, int width, int height);

  // `variant`'s trial, rendered the first time it is asked for: refused by the path, else its
  // budget report; `unfit` (may be empty) then says why that report rules it out ("" when it
  // does not), else it is rendered.
  const Trial& trial(const std::string& variant,
                     const std::function<std::string(const budget::Report&)>& unfit = {});

  // A rendered trial's error over material `material`'s pixels (material_error.h).
  Comparison compare(const Trial& t, size_t material) const;

 private:
  const Scene& scene_;
  const PathInfo& path_;
  const PathOptions& options_;
  std::string profile_;
  RenderSession session_;
  Image reference_;
  std::vector<int> material_of_pixel_;
  std::map<std::string, Trial> trials_;
};

}  // namespace lt::advise
