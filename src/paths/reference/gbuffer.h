// The float G-buffer the CPU paths shade (reference in double, half in emulated fp16): the scene
// rasterised once through OSMesa into three RGBA32F targets, read back as plain arrays.
#pragma once

#include <string>
#include <vector>

#include "gl/program.h"
#include "paths/path.h"

namespace lt {

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

  const gl::GlslProgram& program() const { return program_; }
  // What `stages()` lists for the G-buffer pass (both CPU paths use the same description).
  std::vector<BuiltStage> stages() const;

 private:
  PathContext ctx_;
  gl::GlslProgram program_;
  gl::FloatTarget target_;
  std::vector<float> position_, normal_, thickness_;
};

}  // namespace lt
