// The textures a material's translucency may read (scene-format extension, docs/maps.md "Thickness
// maps and lobe ramps"): a thickness map (`"thickness": {"texture": "map.png", "channels":
// "r"}`) and an artist's lobe ramp (`"ramp": "ramp.png"`, a W x 1 image replacing t^p).
//
// Both are data, not pictures: an 8-bit file's value v is the number v / 255, never sRGB-decoded
// whatever colour space the file declares (as a normal map is read), because the baker wrote
// the thickness itself into the bytes, and decoding would bend every thickness below 1. EXR maps
// are float (half or float samples, kept as they are).
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "model/texture_sampling.h"

namespace lt {

struct TextureMap {
  std::filesystem::path file;
  std::string channels = "rgb";  // the file's channels that became the texels' rgb
  bool grey = false;             // r = g = b in every texel (one channel chosen, or a grey file)
  int source_bits = 8;           // bits per sample in the file (8, 16, 32)
  bool source_float = false;     // half or float samples (EXR)
  bool srgb_decoded = false;     // an integer file's samples were sRGB-decoded (an albedo map)
  model::Texture texture;        // float rgb, row 0 = the image's bottom row (v = 0)

  // An 8-bit file read as data: its texels are exact in an 8-bit GL texture (GL_RGB8 /
  // GL_LUMINANCE8). A decoded sRGB file is not: its linear texels fall between 8-bit steps.
  bool exact_in_8_bits() const { return !source_float && source_bits == 8 && !srgb_decoded; }
};

// How a file's integer samples become texels: as data (v / 255, thickness maps and ramps) or as
// colour encoded with the sRGB transfer function and decoded to linear (an albedo map,
// scene/albedo_map.h). Float samples (EXR) are linear either way.
enum class TexelEncoding { Data, Srgb };

// The reading, channel selection and texel checks every material map shares (the functions
// below and load_albedo_map): `what` names the map in errors ("thickness map").
std::shared_ptr<TextureMap> load_texture_map(const std::filesystem::path& file,
                                             const std::string& channels,
                                             const std::string& scene_file, const std::string& key,
                                             const char* what,
                                             TexelEncoding encoding = TexelEncoding::Data);

// The values `"channels"` may take; `"rgb"` is the default.
inline constexpr const char* kThicknessChannels[] = {"rgb", "r", "g", "b", "a"};
bool is_thickness_channels(const std::string& channels);

// Reads the map, selects `channels` (a single channel becomes grey), and checks every texel is
// a thickness: finite and in [0, kMaxColour]. Every failure is InputError(scene_file, key,
// "...") naming the map's file: not found, unreadable, no pixels, a NaN/Inf or out-of-range
// texel (its x, y counted from the image's top-left, as viewers show them), a channel the image
// lacks.
std::shared_ptr<const TextureMap> load_thickness_map(const std::filesystem::path& file,
                                                     const std::string& channels,
                                                     const std::string& scene_file,
                                                     const std::string& key);

// A lobe ramp: the same reading and checks (all channels: a grey file is a grey ramp, an rgb file
// tints per channel), and the image must be one row high (a W x 1 image): a taller one is refused
// rather than reduced to one of its rows, which would silently ignore the rest of the artist's
// picture.
std::shared_ptr<const TextureMap> load_lobe_ramp(const std::filesystem::path& file,
                                                 const std::string& scene_file,
                                                 const std::string& key);

}  // namespace lt
