// The bench's noise-free cost axis (issue 11): the operations a frame executes, from what the
// path built (Path::work) and what was drawn (pixels each material covers, vertices each
// material's objects have). The same on every machine, unlike milliseconds under llvmpipe.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "paths/path.h"

namespace lt {

// What a scene draws at one size, per material (scene.materials order).
struct SceneCoverage {
  std::vector<double> pixels, vertices;
};

// `pixels` from the G-buffer (covered_pixels_by_material), vertices from the scene's objects.
SceneCoverage scene_coverage(const Scene& scene, std::vector<double> covered_pixels);

struct FrameWork {
  double pixel_ops = 0, vertex_ops = 0;
  std::string pixel_operation, vertex_operation;  // from WorkModel
  double total() const { return pixel_ops + vertex_ops; }
};

// Sum over materials of per_pixel x pixels + per_vertex x vertices; nullopt when the path counts
// nothing (its WorkModel says why).
std::optional<FrameWork> frame_work(const WorkModel& model, const SceneCoverage& coverage);

}  // namespace lt
