// A material's albedo map (scene-format extension, docs/maps.md "Albedo maps"): `"albedo_map":
// "wood.png"` on a material, or a glTF material's baseColorTexture. Its rgb at the mesh's UVs
// multiplies the material's albedo: the seed's cDiffuseAlbedo read from a texture, so it scales
// the diffuse and the translucency terms (and the ambient light) alike.
//
// Unlike a thickness map it is a picture: integer samples (PNG, JPEG, 8 or 16 bits) are colour
// encoded with the sRGB transfer function and are decoded to linear before any filtering, as
// glTF requires of base colour textures [glTF 2.0 spec 3.9.2 Metallic-Roughness Material] and as
// every authoring tool writes them; float samples (EXR) are linear already. Alpha is not read.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "load/thickness_map.h"

namespace lt {

// Reads and decodes the map (image/srgb.h), with the checks and errors of load_thickness_map,
// naming it "albedo map". `wrap` is its sampler's (a glTF sampler's wrapS/wrapT; scene JSON maps
// clamp to the edge, like thickness maps).
std::shared_ptr<TextureMap> load_albedo_map(const std::filesystem::path& file,
                                            const std::string& scene_file, const std::string& key,
                                            TextureWrap wrap_s = TextureWrap::ClampToEdge,
                                            TextureWrap wrap_t = TextureWrap::ClampToEdge);

}  // namespace lt
