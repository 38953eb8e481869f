// A material's map once read (a thickness map, an artist's lobe ramp, an albedo map): its
// texels and where they came from. Plain data, what every path reads; src/load/ reads the files
// into it (load/thickness_map.h, load/albedo_map.h) and model/texture_sampling.h samples it.
//
// Orientation: v = 0 is the BOTTOM row of the image, v = 1 the top (OpenGL's convention, and
// the one the UV baker writes maps in). The texels are stored in that order too (row 0 is the
// image's bottom row), which is the order glTexImage2D takes them in, so a GL path uploads
// `texels` as they are.
#pragma once

#include <filesystem>
#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace lt {

// What a coordinate beyond [0, 1] reads (GL_TEXTURE_WRAP_S/T; a glTF sampler's wrapS/wrapT
// names the same three GL enums [glTF 2.0 spec 3.8.4 Samplers]). Thickness maps and ramps are
// always ClampToEdge; an albedo map from a glTF sampler may repeat.
enum class TextureWrap { ClampToEdge, Repeat, MirroredRepeat };

// A texture as the GL paths upload it.
struct Texture {
  int width = 0, height = 0;
  std::vector<float> texels;  // width * height * 3 (rgb), row 0 = bottom row of the image (v = 0)
  TextureWrap wrap_s = TextureWrap::ClampToEdge, wrap_t = TextureWrap::ClampToEdge;

  glm::dvec3 texel(int x, int y) const {
    const float* t = &texels[(static_cast<size_t>(y) * width + x) * 3];
    return {t[0], t[1], t[2]};
  }
};

// Both kinds of map are data or colour as docs/maps.md says: a thickness map's or ramp's 8-bit
// value v is the number v / 255, never sRGB-decoded (the baker wrote the thickness itself into
// the bytes); an albedo map is a picture, decoded from sRGB. EXR maps are float either way.
struct TextureMap {
  std::filesystem::path file;
  std::string channels = "rgb";  // the file's channels that became the texels' rgb
  bool grey = false;             // r = g = b in every texel (one channel chosen, or a grey file)
  int source_bits = 8;           // bits per sample in the file (8, 16, 32)
  bool source_float = false;     // half or float samples (EXR)
  bool srgb_decoded = false;     // an integer file's samples were sRGB-decoded (an albedo map)
  Texture texture;               // float rgb, row 0 = the image's bottom row (v = 0)

  // An 8-bit file read as data: its texels are exact in an 8-bit GL texture (GL_RGB8 /
  // GL_LUMINANCE8). A decoded sRGB file is not: its linear texels fall between 8-bit steps.
  bool exact_in_8_bits() const { return !source_float && source_bits == 8 && !srgb_decoded; }
};

// The values a thickness map's `"channels"` may take; `"rgb"` is the default.
inline constexpr const char* kThicknessChannels[] = {"rgb", "r", "g", "b", "a"};
inline bool is_thickness_channels(const std::string& channels) {
  for (const char* c : kThicknessChannels)
    if (channels == c) return true;
  return false;
}

}  // namespace lt
