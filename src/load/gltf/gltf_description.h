// A glTF file described, not decoded: what the parse stage (the node walk, gltf_importer.h) makes
// of it, and what the load stage (gltf_scene.h) decodes into the Scene. Which primitives become
// objects, placed where, drawn with which material (its factors and extensions mapped, its base
// colour texture named by image and sampler), the lights and cameras, and the notes `info` prints.
// tinygltf has read the bytes already (the file, its buffers, its images' encoded bytes:
// gltf_document.h says why); no accessor and no image is decoded until the load stage.
#pragma once

#include <glm/glm.hpp>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "load/gltf/gltf_document.h"
#include "scene/scene.h"

namespace lt::gltf {

// The UVs an albedo map reads: TEXCOORD_<set>, then `transform` (KHR_texture_transform's
// T * R * S, in glTF's UV space where v grows downwards), before the importer's v flip.
struct TextureCoordinates {
  int set = 0;
  std::optional<glm::dmat3> transform;
};

// A material's baseColorTexture, its texture, image and sampler checked: /images/{image}'s
// encoded bytes become the albedo map when it is loaded.
struct TextureDescription {
  std::string pointer;  // ".../pbrMetallicRoughness/baseColorTexture"
  int image = -1;
  TextureWrap wrap_s = TextureWrap::Repeat, wrap_t = TextureWrap::Repeat;
  TextureCoordinates coordinates;
  std::size_t notes_at = 0;  // its load notes go before GltfDescription::notes[notes_at]
};

// A material appended to the Scene's: `material.albedo_map` is empty until `texture` is loaded
// (or set already by a scene's override, which wins and reads TEXCOORD_0 as it is).
struct GltfMaterial {
  Material material;
  std::optional<TextureDescription> texture;
};

// How a primitive of glTF material N is drawn: the Scene::materials index, and the UVs that
// material's albedo map reads (its texture's texCoord and KHR_texture_transform; TEXCOORD_0 as
// it is for a scene's material or a scene's albedo map). Decided once, when the material is
// mapped, and kept together: an object that finds the material mapped already (a JSON scene's
// second object of the file) reads what the first one read.
struct MappedMaterial {
  int index = 0;  // a Scene::materials index
  TextureCoordinates uv;
};

// /meshes/{mesh}/primitives/{primitive} as one SceneObject, placed by its node's world matrix.
struct PrimitiveDescription {
  int mesh = 0, primitive = 0;
  MappedMaterial material;
  glm::dmat4 world{1.0};
  std::string node_ptr;      // "/nodes/3", for errors
  std::size_t notes_at = 0;  // as TextureDescription's
};

// A camera on a node of the scene, with the node's world matrix.
struct CameraInstance {
  int camera, node;
  glm::dmat4 world;
};

struct GltfDescription {
  std::shared_ptr<const Document> doc;
  std::size_t first_material = 0;  // the Scene::materials index of materials[0]
  std::vector<GltfMaterial> materials;
  std::vector<PrimitiveDescription> primitives;  // in the walk's order
  std::vector<Light> lights;
  std::vector<CameraInstance> cameras;
  std::vector<std::string> notes, warnings;
};

}  // namespace lt::gltf
