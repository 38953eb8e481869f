// The textures a material's translucency may read (scene-format extension, docs/maps.md "Thickness
// maps and lobe ramps"): a thickness map (`"thickness": {"texture": "map.png", "channels":
// "r"}`) and an artist's lobe ramp (`"ramp": "ramp.png"`, a W x 1 image replacing t^p).
//
// Both are data, not pictures: an 8-bit file's value v is the number v / 255, never sRGB-decoded
// whatever colour space the file declares (as a normal map is read), because the baker wrote
// the thickness itself into the bytes, and decoding would bend every thickness below 1. EXR maps
// are float (half or float samples, kept as they are). What they become is scene/texture_map.h.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "scene/texture_map.h"

namespace lt {

// How a file's integer samples become texels: as data (v / 255, thickness maps and ramps) or as
// colour encoded with the sRGB transfer function and decoded to linear (an albedo map,
// load/albedo_map.h). Float samples (EXR) are linear either way.
enum class TexelEncoding { Data, Srgb };

// The reading, channel selection and texel checks every material map shares (the functions
// below and load_albedo_map): `what` names the map in errors ("thickness map").
std::shared_ptr<TextureMap> load_texture_map(const std::filesystem::path& file,
                                             const std::string& channels,
                                             const std::string& scene_file, const std::string& key,
                                             const char* what,
                                             TexelEncoding encoding = TexelEncoding::Data);

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
