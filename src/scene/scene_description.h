// A scene file as written, validated, before anything it names is read: what parse_scene
// (scene/scene_parse.h) makes of a scene JSON with no I/O beyond the file itself, and what
// load_scene (load/load_scene.h) turns into the Scene every path draws, reading the meshes, the
// glTF files and the maps. Every key is checked here, so a typo is reported before any file I/O.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace lt {

// A map a material names (scene-format.md, docs/maps.md): read when the scene is loaded.
struct MapReference {
  enum class Kind { ThicknessMap, Ramp, AlbedoMap };
  Kind kind = Kind::ThicknessMap;
  std::filesystem::path file;    // resolved against the scene file's folder
  std::string channels = "rgb";  // a thickness map's "channels"
  std::string key;               // "materials.marble.translucency.thickness.texture", for errors
};

// A material with its maps unread: `material`'s map pointers are empty until it is loaded.
struct MaterialDescription {
  Material material;
  std::vector<MapReference> maps;  // in the order they are read
};

// One entry of a glTF object's "materials" (scene-format.md): the scene material's keys given
// to the file's materials that `selector` names, without editing the file.
struct MaterialOverride {
  std::string selector;  // a glTF material's name, "#N" for /materials/N, or "*" for every one
  std::string key;       // "objects[0].materials.Body", for errors and notes
  bool albedo_given = false;
  Material material;  // albedo (if given) and translucency (if set) replace the file's mapping
  std::vector<MapReference> maps;
};

// One of "objects": a mesh file, or the meshes of a glTF file (one node's subtree, or its
// scene), placed by `transform` after the file's own node transforms.
struct ObjectDescription {
  enum class Source { Mesh, Gltf };
  Source source = Source::Mesh;
  std::string key;             // "objects[3]", for errors of the scene file
  std::filesystem::path path;  // the mesh or glTF file, resolved against the scene's folder
  int material = 0;            // an index into materials; a glTF object's -1: the file's own
  Transform transform;
  // A glTF object's:
  std::string node;                         // empty: the file's scene
  std::vector<MaterialOverride> overrides;  // instead of `material`
  std::string overrides_json;  // the "materials" value as written: objects that share it share
                               // the file's mapped materials
  const char* file_key() const { return source == Source::Gltf ? "gltf" : "mesh"; }
};

struct SceneDescription : SceneSettings {
  std::vector<MaterialDescription> materials;
  std::vector<ObjectDescription> objects;  // in the file's order
};

}  // namespace lt
