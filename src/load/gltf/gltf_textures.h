// A glTF material's baseColorTexture (glTF 2.0 §3.9.2, textureInfo §5.22, texture §5.29, image
// §3.8.3, sampler §3.8.4) as the material's albedo map (load/albedo_map.h), and where its
// coordinates come from: the texCoord set and KHR_texture_transform's offset, rotation and scale,
// which the importer applies to the primitive's UVs (an affine map of the UVs is exact on the
// interpolated coordinates, so the paths need no texture matrix).
#pragma once

#include <memory>

#include "load/gltf/gltf_description.h"
#include "load/gltf/gltf_notes.h"

namespace lt::gltf {

// The parse stage: the textureInfo at `pointer` (ending in /baseColorTexture), its texture,
// image and sampler. Throws InputError naming the pointer for: a texture, image or sampler that
// does not exist, a texture without an image source (an extension image such as
// KHR_texture_basisu or EXT_texture_webp), a wrap mode glTF does not define, and a
// KHR_texture_transform with a bad value. Filters other than LINEAR are noted: every path samples
// GL_LINEAR without mipmaps.
TextureDescription describe_base_colour_texture(const Document& doc, const std::string& pointer,
                                                Notes& notes);

// The load stage: the image decoded from sRGB (its PNG or JPEG bytes, from a file, a data URI or
// a GLB buffer view). Throws InputError naming the image's pointer for an image the reader refuses.
std::shared_ptr<const TextureMap> load_base_colour_texture(const Document& doc,
                                                           const TextureDescription& texture,
                                                           Notes& notes);

// TEXCOORD_n's UVs in glTF's space (v down) after `c.transform`, then flipped to OpenGL's
// convention (v = 0 at the bottom row): what TriangleMesh::uvs holds.
glm::dvec2 importer_uv(const TextureCoordinates& c, glm::dvec2 gltf_uv);

}  // namespace lt::gltf
