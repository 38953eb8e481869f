// A scene loaded: its description (scene/scene_description.h) with every file it names read --
// the meshes in world space (mesh/mesh_io.h), the glTF files (load/gltf/), the maps
// (load/thickness_map.h, load/albedo_map.h) -- into the Scene every path draws. Every command
// that takes a scene goes through load_scene(path).
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene.h"
#include "scene/scene_description.h"

namespace lt {

struct SceneOptions {
  std::string camera;  // glTF scenes: the camera (or its node) to look through, by name
  // A scene with no light and no ambient light gets the default rig (scene/default_lights.h);
  // `--lights none` turns this off and the scene renders unlit, as it says.
  bool default_lights = true;
};

// Reads every file `description` names, in this order: that each object's file is there and is
// a file to read (an InputError naming the scene's key), the maps (materials', then the glTF
// objects' overrides'), the meshes, then the glTF objects (load/gltf/gltf_scene.h). Errors inside
// a file name that file and its line or JSON pointer; the scene's own checks (the vertex limit,
// vertex colours for "thickness": "vertex", UVs for a map) name the scene's key.
Scene load_scene(SceneDescription description);

// Parses (scene/scene_parse.h) and loads. A .gltf or .glb is described then loaded as a whole
// scene (load/gltf/gltf_scene.h), its errors naming the JSON pointer. Adds the default lights when
// `options` asks and the scene has none, and prints the scene's warnings, once.
Scene load_scene(const std::filesystem::path& path, const SceneOptions& options = {});

}  // namespace lt
