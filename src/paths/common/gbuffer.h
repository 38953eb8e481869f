// The float G-buffer the CPU paths shade (reference in double, half in emulated fp16): the scene
// rasterised once through OSMesa into two or three RGBA32F targets (gbuffer_layout.h), read back
// as plain arrays.
#pragma once

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "core/parallel_rows.h"
#include "gl/program.h"
#include "paths/common/gbuffer_layout.h"
#include "paths/common/pixel_run.h"
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
  GBuffer(const PathContext& ctx, const std::string& user,
          GreyThickness grey = GreyThickness::OneChannel);

  // Draws every mesh and reads the targets back (bottom row first, like glReadPixels).
  void rasterise();

  int width() const { return ctx_.width; }
  int height() const { return ctx_.height; }
  // Only the pixels of the geometry's covered_rect are cleared and read back (the rest hold
  // nothing): at 1280x720 the read-back of all of them was most of a CPU path's frame on the
  // demo scenes whose objects fill part of it (issue 39).
  bool in_rect(int x, int gy) const { return rect_.contains(x, gy); }
  // Index of the first float of pixel (x, gy) of the rectangle in every array; gy counts rows
  // bottom-up.
  size_t index(int x, int gy) const {
    return (static_cast<size_t>(gy - rect_.y) * rect_.width + (x - rect_.x)) * 4;
  }
  // The material index of pixel g, -1 where nothing is covered: the position target's alpha is
  // the index + 1, written by the G-buffer fragment shader over a target cleared to 0, so
  // coverage and material share one channel and the other targets need no clear (issue 39).
  int material(size_t g) const { return material_of(&position_[g]); }
  // Threads the CPU paths shade on: every core.
  static unsigned threads() { return worker_threads(); }

  // Fills `image` (top row first): background with alpha 0 where nothing is covered, and with
  // alpha 1 where something is, the colours `shade(run, shaded, worker)` writes into `shaded`
  // for each run of covered pixels of one row and one material (pixel_run.h: vectorised
  // shading takes a run's lanes at once). `worker` < threads() lets the caller keep per-thread
  // counters without locks. Returns the number of covered pixels. Pixels outside the covered
  // rectangle are written only when `image` is made (neither the rectangle nor a path's
  // background changes between its frames), so a frame costs the rectangle's pixels alone.
  template <class ShadeRun>
  size_t shade_covered(Image& image, const glm::dvec3& background, ShadeRun&& shade) const {
    const int w = ctx_.width, h = ctx_.height;
    // The last frame's image is reused as it is: a fresh one would be 15 MB of page faults a
    // frame at 1280x720, noise the bench would time.
    if (image.width != w || image.height != h) {
      image = Image(w, h);
      for (size_t i = 0; i < image.pixel_count(); ++i)
        for (int c = 0; c < 3; ++c) image.rgba[i * 4 + c] = static_cast<float>(background[c]);
    }
    std::vector<size_t> covered(threads(), 0);
    for_each_row_in_parallel(rect_.height, [&](int rect_row, unsigned worker) {
      // One row loop a layout, so the gather tests no flag per pixel.
      covered[worker] +=
          layout_.targets() == 3
              ? shade_row<Gather::ThreeTargets>(rect_row, image, background, shade, worker)
          : layout_.grey_thickness
              ? shade_row<Gather::GreyThickness>(rect_row, image, background, shade, worker)
              : shade_row<Gather::TwoTargets>(rect_row, image, background, shade, worker);
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
  GBufferLayout layout_;
  gl::GlslProgram program_;
  gl::PixelRect rect_;
  gl::FloatTarget target_;
  // Targets 0, 1 and 2 as read back (gbuffer_layout.h); the third only when there is one.
  std::vector<float> position_, normal_, thickness_;

  // Where a run's lanes come from. Lanes no material reads are 0 (the shader's 0, or set so
  // once a row): the thickness without vertex thickness, the uv without a map.
  enum class Gather {
    TwoTargets,     // thickness and uv 0
    GreyThickness,  // thickness: target 1's alpha in all three channels; uv 0
    ThreeTargets,   // u: target 1's alpha; thickness, v: target 2
  };

  // Row rect_row of the rectangle, as shade_covered says; returns its covered pixels.
  template <Gather kGather, class ShadeRun>
  size_t shade_row(int rect_row, Image& image, const glm::dvec3& background, ShadeRun& shade,
                   unsigned worker) const {
    const int gy = rect_.y + rect_row;
    // The three targets' texels of the row, walked side by side (4 floats a pixel each).
    const size_t g0 = index(rect_.x, gy);
    const float* const position = position_.data() + g0;
    const float* const normal = normal_.data() + g0;
    const float* const thickness =
        kGather == Gather::ThreeTargets ? thickness_.data() + g0 : nullptr;
    // G-buffer rows count bottom-up, image rows top-down.
    float* const out = image.at(rect_.x, ctx_.height - 1 - gy);
    const float uncovered[4] = {static_cast<float>(background[0]),
                                static_cast<float>(background[1]),
                                static_cast<float>(background[2]), 0.0f};
    PixelRun run;
    if constexpr (kGather == Gather::TwoTargets) zero_thickness_lanes(run);
    if constexpr (kGather != Gather::ThreeTargets) zero_uv_lanes(run);
    ShadedRun shaded;
    int run_x[kPixelRunCapacity];  // each lane's pixel, as a float offset into the row
    size_t covered = 0;
    auto flush = [&] {
      if (run.count == 0) return;
      pad(run);
      shade(static_cast<const PixelRun&>(run), shaded, worker);
      for (size_t i = 0; i < run.count; ++i) {
        float* o = out + run_x[i];
        for (int c = 0; c < 3; ++c) o[c] = shaded.rgb[c][i];
        o[3] = 1;
      }
      covered += run.count;
      run.count = 0;
    };
    for (int g = 0; g < rect_.width * 4; g += 4) {
      const int m = material_of(position + g);
      if (m < 0) {
        std::copy(uncovered, uncovered + 4, out + g);
        continue;
      }
      if (run.count > 0 && (m != run.material || run.count == kPixelRunCapacity)) flush();
      run.material = m;
      run_x[run.count] = g;
      const size_t i = run.count++;
      for (int c = 0; c < 3; ++c) {
        run.position[c][i] = position[g + c];
        run.normal[c][i] = normal[g + c];
      }
      if constexpr (kGather == Gather::GreyThickness) {
        for (int c = 0; c < 3; ++c) run.thickness[c][i] = normal[g + 3];
      }
      if constexpr (kGather == Gather::ThreeTargets) {
        for (int c = 0; c < 3; ++c) run.thickness[c][i] = thickness[g + c];
        run.uv[0][i] = normal[g + 3];
        run.uv[1][i] = thickness[g + 3];
      }
    }
    flush();
    return covered;
  }
  // The material of a position texel (position.xyz, material + 1), -1 where nothing is covered.
  static int material_of(const float* position) { return static_cast<int>(position[3] + 0.5f) - 1; }
  // Every lane of the run's thickness, or of its uv, set to 0.
  static void zero_thickness_lanes(PixelRun& run);
  static void zero_uv_lanes(PixelRun& run);
  // Lanes past run.count up to the widest vector's multiple (kPixelRunPadding): lane 0 again.
  static void pad(PixelRun& run);
};

}  // namespace lt
