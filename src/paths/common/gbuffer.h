// The float G-buffer the CPU paths shade (reference in double, half in emulated fp16): the scene
// rasterised once through OSMesa into three RGBA32F targets, read back as plain arrays.
#pragma once

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "core/parallel_rows.h"
#include "gl/program.h"
#include "paths/path.h"

namespace lt {

// The scene as the G-buffer's shading sees it: lights moved into camera-relative space (the
// space the G-buffer positions are in), and no meshes (shading needs lights and materials only;
// copying every mesh per path would cost a full scene's memory for nothing).
Scene camera_relative_lights(const PathContext& ctx);

// The material each pixel of the final image shows (top row first, -1 where nothing is covered),
// from one G-buffer rasterisation: advise measures a material's error on its own pixels.
std::vector<int> material_per_pixel(const PathContext& ctx);

// The pixels each material covers (scene.materials order), counted from material_per_pixel: what
// the bench's work axis multiplies a path's per-pixel operations by.
std::vector<double> covered_pixels_by_material(const PathContext& ctx);

class GBuffer {
 public:
  // Builds the G-buffer program and targets; `user` names the path in extension errors.
  GBuffer(const PathContext& ctx, const std::string& user);

  // Draws every mesh and reads the three targets back (bottom row first, like glReadPixels).
  void rasterise();

  int width() const { return ctx_.width; }
  int height() const { return ctx_.height; }
  // Index of the first float of pixel (x, gy) in every array; gy counts rows bottom-up.
  size_t index(int x, int gy) const { return (static_cast<size_t>(gy) * ctx_.width + x) * 4; }
  // Alpha of the position target is the coverage the G-buffer fragment shader writes.
  bool covered(size_t g) const { return position_[g + 3] > 0.5f; }
  // The material index travels as a float in the normal target's alpha.
  int material(size_t g) const { return static_cast<int>(normal_[g + 3] + 0.5f); }
  // Camera-relative position, interpolated (not renormalised) normal, vertex thickness: xyz.
  const float* position(size_t g) const { return &position_[g]; }
  const float* normal(size_t g) const { return &normal_[g]; }
  const float* thickness(size_t g) const { return &thickness_[g]; }
  // The interpolated (u, v) of a material that samples a map; (0, 0) in a scene without maps
  // (the fourth target is only built for a scene with one).
  glm::dvec2 uv(size_t g) const {
    return uv_.empty() ? glm::dvec2(0) : glm::dvec2(uv_[g], uv_[g + 1]);
  }

  // Threads the CPU paths shade on: every core.
  static unsigned threads() { return worker_threads(); }

  // Fills `image` (top row first): background with alpha 0 where nothing is covered, and
  // `shade(g, rgb, worker)` with alpha 1 where something is; `worker` < threads() lets the caller
  // keep per-thread counters without locks. Returns the number of covered pixels.
  template <class ShadePixel>
  size_t shade_covered(Image& image, const glm::dvec3& background, ShadePixel&& shade) const {
    const int w = ctx_.width, h = ctx_.height;
    // Every pixel is written below, so the last frame's image is reused as it is: a fresh one
    // would be 15 MB of page faults a frame at 1280x720, noise the bench would time.
    if (image.width != w || image.height != h) image = Image(w, h);
    std::vector<size_t> covered(threads(), 0);
    for_each_row_in_parallel(h, [&](int gy, unsigned worker) {
      for (int x = 0; x < w; ++x) {
        const size_t g = index(x, gy);         // G-buffer row gy, bottom-up
        float* out = image.at(x, h - 1 - gy);  // image rows top-down
        if (!this->covered(g)) {
          for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(background[c]);
          out[3] = 0;
          continue;
        }
        ++covered[worker];
        shade(g, out, worker);
        out[3] = 1;
      }
    });
    size_t total = 0;
    for (size_t c : covered) total += c;
    return total;
  }

  const gl::GlslProgram& program() const { return program_; }
  // What `stages()` lists for the G-buffer pass (both CPU paths use the same description).
  std::vector<BuiltStage> stages() const;

 private:
  PathContext ctx_;
  gl::GlslProgram program_;
  bool uv_target_ = false;  // a material samples a map: the fourth target holds (u, v)
  gl::FloatTarget target_;
  std::vector<float> position_, normal_, thickness_, uv_;
};

}  // namespace lt
