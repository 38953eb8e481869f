// A thickness map or a lobe ramp (scene/thickness_map.h) as a GL texture: GL_TEXTURE_2D,
// GL_LINEAR without mipmaps, GL_CLAMP_TO_EDGE, the texels uploaded as they are stored (row 0 =
// v = 0, model/texture_sampling.h), so GL's sampling is the one the reference computes in double.
// Shared by the glsl, arbfp and combiners paths: one upload, one description of its precision.
#pragma once

#include <string>

#include "gl/context.h"
#include "scene/thickness_map.h"

namespace lt::gl {

// GL_LINEAR without mipmaps and GL_CLAMP_TO_EDGE (s and t) for the texture bound to `target`
// (1D, 2D or a cube map): the sampling the reference computes in double
// (model/texture_sampling.h), and every lookup table's: coordinates beyond the end texel centres
// read the end texels, which saturates a table's t.
void set_linear_clamp_to_edge(GLenum target);

class MapTexture {
 public:
  // Needs a current context.
  //  - 8-bit files: GL_RGB8 from the bytes (v / 255 is what the file held: exact).
  //  - 16-bit integer files: GL_RGB16 (exact).
  //  - half EXR: GL_RGB16F_ARB (exact); float EXR: GL_RGB32F_ARB (exact), both through
  //    GL_ARB_texture_float, which llvmpipe offers. Without it, GL_RGB16: the texels rounded to
  //    1/65535 (the loss is said in description()), values above 1 clamped to 1.
  MapTexture(const Context& gl, const TextureMap& map);
  ~MapTexture();
  MapTexture(const MapTexture&) = delete;
  MapTexture& operator=(const MapTexture&) = delete;

  GLuint id() const { return id_; }
  // "GL_RGB8 64x64 (exact: 8-bit file), GL_LINEAR, CLAMP_TO_EDGE", for `info`.
  const std::string& description() const { return description_; }

 private:
  GLuint id_ = 0;
  std::string description_;
};

}  // namespace lt::gl
