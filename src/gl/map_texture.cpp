#include "gl/map_texture.h"

#include <cmath>
#include <vector>

namespace lt::gl {

void set_linear_clamp_to_edge(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // a 1D texture ignores it
}

MapTexture::MapTexture(const Context& gl, const TextureMap& map) {
  const model::Texture& t = map.texture;
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  set_linear_clamp_to_edge(GL_TEXTURE_2D);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::string size = std::to_string(t.width) + "x" + std::to_string(t.height);
  const bool float_textures = gl.has_extension("GL_ARB_texture_float");
  if (map.exact_in_8_bits()) {
    // The texels are multiples of 1/255: upload the bytes, so GL rounds nothing of its own.
    std::vector<unsigned char> bytes(t.texels.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
      bytes[i] = static_cast<unsigned char>(std::lround(t.texels[i] * 255.0));
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, t.width, t.height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 bytes.data());
    description_ = "GL_RGB8 " + size + " (exact: 8-bit file)";
  } else if (!map.source_float || !float_textures) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16, t.width, t.height, 0, GL_RGB, GL_FLOAT,
                 t.texels.data());
    description_ =
        "GL_RGB16 " + size +
        (map.source_float ? " (GL_ARB_texture_float missing: float texels rounded to 1/65535, "
                            "clamped to [0, 1])"
                          : " (exact: 16-bit file)");
  } else {
    const bool half = map.source_bits == 16;
    // A half file's texels are halves already, so the float->half conversion is exact.
    glTexImage2D(GL_TEXTURE_2D, 0, half ? GL_RGB16F_ARB : GL_RGB32F_ARB, t.width, t.height, 0,
                 GL_RGB, GL_FLOAT, t.texels.data());
    description_ = std::string(half ? "GL_RGB16F " : "GL_RGB32F ") + size +
                   (half ? " (exact: half file)" : " (exact: float file)");
  }
  description_ += ", GL_LINEAR, CLAMP_TO_EDGE";
  glBindTexture(GL_TEXTURE_2D, 0);
  check_error("uploading a thickness map or ramp");
}

MapTexture::~MapTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

}  // namespace lt::gl
