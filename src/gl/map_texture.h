// A thickness map, a lobe ramp (load/thickness_map.h) or an albedo map (load/albedo_map.h) as
// a GL texture: GL_TEXTURE_2D, GL_LINEAR without mipmaps, GL_CLAMP_TO_EDGE (an albedo map: its
// sampler's wrap), the texels uploaded in the widest format the
// path's hardware class filters (row 0 = v = 0, model/texture_sampling.h), so GL's sampling is
// the reference's, in that format's precision. Shared by the glsl, arbfp and combiners paths:
// one upload, one description of its precision.
#pragma once

#include <string>

#include "gl/context.h"
#include "model/texture_sampling.h"

namespace lt::gl {

// The texel formats a path's hardware class can filter, which decides what a file wider than
// 8 bits (a 16-bit PNG, a half or float EXR) becomes.
enum class MapTexelClass {
  // GL 2.0 / ps_2_x-class parts (glsl, arbfp): fp16 is the widest float texture they filter
  // (GeForce 6 filters fp16; fp32 filtering came only with the DX10 parts), so a float map is
  // GL_RGB16F, values above 1 kept; a 16-bit file GL_RGB16.
  Fp16,
  // GL 1.3-class parts (combiners: GeForce 2/3, Radeon 7500): no float or 16-bit textures, so
  // every map is GL_RGB8: each texel clamped to [0, 1] (the combine stages clamp there anyway)
  // and rounded to the nearest 1/255, at most 0.5/255 off.
  Unorm8,
};

// GL_LINEAR without mipmaps and GL_CLAMP_TO_EDGE (s and t) for the texture bound to `target`
// (1D, 2D or a cube map): the sampling the reference computes in double
// (model/texture_sampling.h), and every lookup table's: coordinates beyond the end texel centres
// read the end texels, which saturates a table's t.
void set_linear_clamp_to_edge(GLenum target);

class MapTexture {
 public:
  // Needs a current context. An 8-bit file is GL_RGB8 from its bytes (v / 255 is what the file
  // held: exact) for either class. Fp16: a half EXR is exact in GL_RGB16F; a float EXR is
  // rounded to half by the upload (2^-12 relative at most); a 16-bit file is GL_RGB16 (exact).
  // Without GL_ARB_texture_float (llvmpipe has it), float files fall back to GL_RGB16: the
  // texels rounded to 1/65535 and clamped to [0, 1] (said in description()).
  MapTexture(const Context& gl, const TextureMap& map, MapTexelClass texel_class);
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
