// The rasteriser of the gx path (gx.md §3: rasterisation may use OSMesa): draws every object with
// the per-vertex outputs of the emulated XF as attributes into RGBA32F targets and reads them
// back, so the CPU can run the integer TEV on every covered pixel. The colours come back as
// floats (0..255) and are truncated to 8 bits by the pixel stage.
#pragma once

#include <memory>
#include <vector>

#include "gl/program.h"
#include "paths/gx/vertex_stage.h"
#include "paths/path.h"

namespace lt::gx {

// The emulator reads the (s, t, q) of at most this many texgens: three targets hold the
// colours and coverage, and llvmpipe draws to 8.
inline constexpr int kRasterisedTexGens = 5;

class AttributeRasteriser {
 public:
  AttributeRasteriser(const PathContext& ctx, int texgens);
  ~AttributeRasteriser();
  AttributeRasteriser(const AttributeRasteriser&) = delete;
  AttributeRasteriser& operator=(const AttributeRasteriser&) = delete;

  // Draws object i with outputs[i] (an object with no outputs this pass still draws, for depth,
  // with zero attributes) under its GX cull mode cull_modes[i] (gx_state.h), and reads every
  // target back.
  void rasterise(const std::vector<const VertexOutputs*>& outputs,
                 const std::vector<u8>& cull_modes);

  int texgens() const { return texgens_; }
  int width() const { return ctx_.width; }
  int height() const { return ctx_.height; }
  // Pixel (x, gy), gy counting rows bottom-up, as the first float index of its RGBA in every
  // target.
  size_t index(int x, int gy) const { return (static_cast<size_t>(gy) * ctx_.width + x) * 4; }
  bool covered(size_t g) const { return meta_[g + 1] > 0.5f; }
  int material(size_t g) const { return static_cast<int>(meta_[g] + 0.5f); }
  const float* color(int channel, size_t g) const {
    return &colors_[static_cast<size_t>(channel)][g];
  }
  const float* texcoord(int texgen, size_t g) const {
    return &texcoords_[static_cast<size_t>(texgen)][g];
  }
  const gl::GlslProgram& program() const { return *program_; }

 private:
  PathContext ctx_;
  int texgens_;
  std::unique_ptr<gl::GlslProgram> program_;
  gl::FloatTarget target_;
  std::vector<std::vector<GLuint>> buffers_;  // per object: colour0, colour1, texcoords...
  std::vector<float> meta_;
  std::array<std::vector<float>, 2> colors_;
  std::vector<std::vector<float>> texcoords_;
};

}  // namespace lt::gx
