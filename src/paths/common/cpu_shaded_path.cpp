#include "paths/common/cpu_shaded_path.h"

#include <chrono>
#include <utility>

#include "core/stopwatch.h"

namespace lt {

CpuShadedPath::CpuShadedPath(const PathContext& ctx, const std::string& gbuffer_user,
                             std::string shading)
    : ctx_(ctx),
      gbuffer_(ctx, gbuffer_user),
      fragments_(gbuffer_user, ctx.geometry),
      shading_(std::move(shading)) {}

void CpuShadedPath::frame() {
  fragments_.begin();
  gbuffer_.rasterise();
  fragments_.end();
  const auto t0 = std::chrono::steady_clock::now();
  shade();
  shading_seconds_ = seconds_since(t0);
}

std::vector<BuiltStage> CpuShadedPath::stages() const {
  std::vector<BuiltStage> out = gbuffer_.stages();
  out.push_back({"shading: " + shading_ + " on " + std::to_string(threads()) +
                     (threads() == 1 ? " thread" : " threads"),
                 "cpu", ""});
  return out;
}

FrameStats CpuShadedPath::frame_stats() const {
  FrameStats s;
  s.shading_seconds = shading_seconds_;
  s.covered_pixels = static_cast<double>(covered_);
  s.threads = threads();
  return s;
}

WorkModel CpuShadedPath::work() const {
  WorkModel w{"CPU light evaluation", "", {}, {}};
  const MaterialWork each{static_cast<double>(ctx_.scene.lights.size()), 0};
  w.by_material.assign(ctx_.scene.materials.size(), each);
  return w;
}

}  // namespace lt
