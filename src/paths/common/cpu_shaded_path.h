// What the CPU paths (reference in double, half in emulated fp16) share: a frame is the float
// G-buffer's rasterisation followed by the path's own shading of every covered pixel, timed on
// its own so the bench can tell the two apart; the image is float.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "paths/common/first_frame_fragments.h"
#include "paths/common/gbuffer.h"
#include "paths/path.h"

namespace lt {

class CpuShadedPath : public Path {
 public:
  // `gbuffer_user` names the path in the G-buffer's messages ("the reference G-buffer");
  // `shading` says how it shades, for `info` ("model::shade in double").
  CpuShadedPath(const PathContext& ctx, const std::string& gbuffer_user, std::string shading);

  void frame() final;
  Image result() override { return image_; }
  bool float_output() const final { return true; }
  std::vector<BuiltStage> stages() const final;
  // Shading time, covered pixels and threads; a path adds its own figures.
  FrameStats frame_stats() const override;
  // model::shade evaluates each light of the scene once a covered pixel.
  WorkModel work() const final;

 protected:
  // Shades every covered pixel of gbuffer_ into image_ and sets covered_.
  virtual void shade() = 0;
  static unsigned threads() { return GBuffer::threads(); }

  PathContext ctx_;
  GBuffer gbuffer_;
  Image image_;
  std::size_t covered_ = 0;

 private:
  FirstFrameFragments fragments_;  // the warning of an empty frame
  std::string shading_;
  double shading_seconds_ = 0;
};

}  // namespace lt
