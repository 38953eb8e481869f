#include "load/thickness_map.h"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "image/image.h"
#include "image/srgb.h"
#include "scene/scene_limits.h"

namespace lt {

namespace {

// The image's channel `name` as an index into read_image's RGBA, or -1 when the file lacks it.
int channel_index(char name, const ImageFileFormat& format) {
  switch (name) {
    case 'r':
      return 0;  // a grey file's grey
    case 'g':
      return format.colour_channels >= 3 ? 1 : -1;
    case 'b':
      return format.colour_channels >= 3 ? 2 : -1;
    case 'a':
      return format.has_alpha ? 3 : -1;
  }
  return -1;
}

}  // namespace

std::shared_ptr<TextureMap> load_texture_map(const std::filesystem::path& file,
                                             const std::string& channels,
                                             const std::string& scene_file, const std::string& key,
                                             const char* what, TexelEncoding encoding) {
  const std::string name = file.string();
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    throw InputError(scene_file, key, std::string(what) + " file not found: " + name);
  }
  ImageFileFormat format;
  Image image;
  try {
    image = read_image(file, format);
  } catch (const InputError& e) {
    throw InputError(scene_file, key, std::string(what) + " file " + name + " " + e.what_only());
  }
  auto map = std::make_shared<TextureMap>();
  map->file = file;
  map->channels = channels;
  map->source_bits = format.bits;
  map->source_float = format.floating;
  map->srgb_decoded = encoding == TexelEncoding::Srgb && !format.floating;
  int source[3] = {0, 1, 2};
  if (channels == "rgb") {
    map->grey = format.colour_channels < 3;
  } else {
    const int c = channel_index(channels[0], format);
    if (c < 0) {
      throw InputError(scene_file, key,
                       std::string(what) + " file " + name + " has no " + channels +
                           " channel (it has " +
                           (format.colour_channels >= 3 ? "r, g, b" : "one grey channel, \"r\"") +
                           (format.has_alpha ? " and a" : "") + ")");
    }
    map->grey = true;
    source[0] = source[1] = source[2] = c;
  }
  Texture& t = map->texture;
  t.width = image.width;
  t.height = image.height;
  t.texels.resize(image.pixel_count() * 3);
  for (int y = 0; y < image.height; ++y) {
    // Row 0 of the texture is the image's bottom row: v = 0 at the bottom (texture_sampling.h).
    const int row = image.height - 1 - y;
    for (int x = 0; x < image.width; ++x) {
      const float* px = image.at(x, y);
      float* texel = &t.texels[(static_cast<size_t>(row) * image.width + x) * 3];
      for (int c = 0; c < 3; ++c) {
        const float v =
            map->srgb_decoded ? static_cast<float>(srgb_to_linear(px[source[c]])) : px[source[c]];
        if (!(v >= 0 && v <= kMaxColour)) {
          std::string msg = std::string(what) + " file " + name + ": texel x " + std::to_string(x) +
                            ", y " + std::to_string(y) + " (from the top left) is ";
          msg.append(std::isfinite(v)
                         ? nlohmann::json(v).dump() + ", out of range (allowed [0, " +
                               nlohmann::json(kMaxColour).dump() + "])"
                         : std::string(std::isnan(v) ? "NaN" : "infinite") + " (not finite)");
          throw InputError(scene_file, key, msg);
        }
        texel[c] = v;
      }
    }
  }
  return map;
}

std::shared_ptr<const TextureMap> load_thickness_map(const std::filesystem::path& file,
                                                     const std::string& channels,
                                                     const std::string& scene_file,
                                                     const std::string& key) {
  return load_texture_map(file, channels, scene_file, key, "thickness map");
}

std::shared_ptr<const TextureMap> load_lobe_ramp(const std::filesystem::path& file,
                                                 const std::string& scene_file,
                                                 const std::string& key) {
  auto ramp = load_texture_map(file, "rgb", scene_file, key, "lobe ramp");
  if (ramp->texture.height != 1) {
    throw InputError(scene_file, key,
                     "lobe ramp file " + file.string() + " is " +
                         std::to_string(ramp->texture.width) + "x" +
                         std::to_string(ramp->texture.height) +
                         ": a ramp is one row high (W x 1), its value at t in [0, 1] read "
                         "left to right");
  }
  return ramp;
}

}  // namespace lt
