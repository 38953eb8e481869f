#include "report/frame_work.h"

#include <algorithm>

namespace lt {

SceneCoverage scene_coverage(const Scene& scene, std::vector<double> covered_pixels) {
  SceneCoverage c;
  c.pixels = std::move(covered_pixels);
  c.pixels.resize(scene.materials.size(), 0.0);
  c.vertices.assign(scene.materials.size(), 0.0);
  for (const SceneObject& o : scene.objects) {
    c.vertices[static_cast<size_t>(o.material)] += static_cast<double>(o.mesh.positions.size());
  }
  return c;
}

std::optional<FrameWork> frame_work(const WorkModel& model, const SceneCoverage& coverage) {
  if (model.by_material.empty()) return std::nullopt;
  FrameWork w;
  w.pixel_operation = model.pixel_operation;
  w.vertex_operation = model.vertex_operation;
  const size_t n = std::min(model.by_material.size(), coverage.pixels.size());
  for (size_t m = 0; m < n; ++m) {
    w.pixel_ops += model.by_material[m].per_pixel * coverage.pixels[m];
    w.vertex_ops += model.by_material[m].per_vertex * coverage.vertices[m];
  }
  return w;
}

}  // namespace lt
