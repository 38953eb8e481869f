#include "gl/map_texture.h"

#include <vector>

#include "image/image.h"

namespace lt::gl {

void set_linear_clamp_to_edge(GLenum target) {
  glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);  // a 1D texture ignores it
}

namespace {

// GL_CLAMP_TO_EDGE, GL_REPEAT or GL_MIRRORED_REPEAT (GL 1.4 core).
GLint gl_wrap(model::Wrap wrap) {
  switch (wrap) {
    case model::Wrap::Repeat:
      return GL_REPEAT;
    case model::Wrap::MirroredRepeat:
      return GL_MIRRORED_REPEAT;
    case model::Wrap::ClampToEdge:
      break;
  }
  return GL_CLAMP_TO_EDGE;
}

}  // namespace

MapTexture::MapTexture(const Context& gl, const TextureMap& map, MapTexelClass texel_class) {
  const model::Texture& t = map.texture;
  glGenTextures(1, &id_);
  glBindTexture(GL_TEXTURE_2D, id_);
  set_linear_clamp_to_edge(GL_TEXTURE_2D);
  // An albedo map's glTF sampler may repeat (model::Wrap); thickness maps and ramps clamp.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap(t.wrap_s));
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap(t.wrap_t));
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  const std::string size = std::to_string(t.width) + "x" + std::to_string(t.height);
  const bool float_textures = gl.has_extension("GL_ARB_texture_float");
  if (map.exact_in_8_bits() || texel_class == MapTexelClass::Unorm8) {
    // Rounded here, not by GL, so the bytes are exactly the nearest 1/255 (an 8-bit file's own
    // bytes come back unchanged).
    std::vector<unsigned char> bytes(t.texels.size());
    for (size_t i = 0; i < bytes.size(); ++i) {
      bytes[i] = to_unorm8(t.texels[i]);
    }
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB8, t.width, t.height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                 bytes.data());
    description_ = "GL_RGB8 " + size +
                   (map.exact_in_8_bits() ? " (exact: 8-bit file)"
                    : map.srgb_decoded
                        ? " (sRGB decoded to linear, rounded to 1/255: GL 1.3 parts have no sRGB "
                          "textures, a port stores the linear colour)"
                        : std::string(map.source_float ? " (a float" : " (a 16-bit") +
                              " file rounded to 1/255, clamped to [0, 1]: "
                              "GL 1.3 parts filter only 8-bit texels)");
  } else if (map.srgb_decoded && float_textures) {
    // The decoded linear colour as half: sRGB decoding before the filter [glTF 2.0 spec 3.9.2]
    // without GL_EXT_texture_sRGB (a GL 2.1 extension the GL 2.0 class lacks); half keeps the
    // decoded darks (1/255 encoded is 3e-4 linear) that an 8-bit linear texture would flatten.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F_ARB, t.width, t.height, 0, GL_RGB, GL_FLOAT,
                 t.texels.data());
    description_ = "GL_RGB16F " + size + " (sRGB decoded to linear, rounded to half)";
  } else if (!map.source_float || !float_textures) {
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16, t.width, t.height, 0, GL_RGB, GL_FLOAT,
                 t.texels.data());
    description_ =
        "GL_RGB16 " + size +
        (map.source_float ? " (GL_ARB_texture_float missing: float texels rounded to 1/65535, "
                            "clamped to [0, 1])"
                          : " (exact: 16-bit file)");
  } else {
    // GL_RGB16F for half and float files alike (MapTexelClass::Fp16): a half file's texels are
    // halves already, so its conversion is exact; a float file's are rounded to half.
    const bool half = map.source_bits == 16;
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB16F_ARB, t.width, t.height, 0, GL_RGB, GL_FLOAT,
                 t.texels.data());
    description_ = "GL_RGB16F " + size +
                   (half ? " (exact: half file)"
                         : " (float file rounded to half: fp16 is the widest float texture "
                           "GL 2.0-class parts filter)");
  }
  description_ += ", GL_LINEAR, ";
  description_ += t.wrap_s == t.wrap_t ? std::string(model::wrap_name(t.wrap_s))
                                       : std::string(model::wrap_name(t.wrap_s)) + " x " +
                                             model::wrap_name(t.wrap_t);
  glBindTexture(GL_TEXTURE_2D, 0);
  check_error("uploading a thickness map or ramp");
}

MapTexture::~MapTexture() {
  if (id_) glDeleteTextures(1, &id_);
}

}  // namespace lt::gl
