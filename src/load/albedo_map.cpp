#include "load/albedo_map.h"

namespace lt {

std::shared_ptr<TextureMap> load_albedo_map(const std::filesystem::path& file,
                                            const std::string& scene_file, const std::string& key,
                                            TextureWrap wrap_s, TextureWrap wrap_t) {
  std::shared_ptr<TextureMap> map =
      load_texture_map(file, "rgb", scene_file, key, "albedo map", TexelEncoding::Srgb);
  map->texture.wrap_s = wrap_s;
  map->texture.wrap_t = wrap_t;
  return map;
}

}  // namespace lt
