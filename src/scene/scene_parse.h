// A scene JSON (scene-format.md) read into its description (scene/scene_description.h): every key
// checked, nothing it names read. A .gltf or .glb scene is described by the glTF parse stage
// (load/gltf/gltf_scene.h), which reads what tinygltf reads: the file, its buffers and images.
#pragma once

#include <filesystem>
#include <string>

#include "scene/scene_description.h"

namespace lt {

// Throws InputError naming the file and the key (e.g. "materials.marble.translucency.power") or
// the line of a JSON syntax error. The files the scene names are resolved against `base_dir`.
SceneDescription parse_scene(const std::string& text, const std::filesystem::path& file_for_errors,
                             const std::filesystem::path& base_dir);

// Reads `path` through the input layer (core/fs.h) and parses it, its files resolved against its
// folder.
SceneDescription parse_scene_file(const std::filesystem::path& path);

}  // namespace lt
