// A whole glTF 2.0 file (.gltf or .glb) as a Scene: its default scene's node hierarchy, meshes,
// materials, KHR_lights_punctual lights and a camera, parsed (described) then loaded (decoded).
// load_scene (load/load_scene.h) calls both for these extensions, so every command that takes a
// scene takes a glTF file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "load/gltf/gltf_description.h"
#include "scene/scene_description.h"

namespace lt::gltf {

// The image size of a glTF scene (glTF has none): 480 rows, and as many columns as the camera's
// aspectRatio asks for (640 without one). `--width/--height` override both.
inline constexpr int kDefaultHeight = 480;
inline constexpr int kDefaultWidth = 640;

// The parse stage: the file read (gltf_document.h) and its default scene described, nothing
// decoded. Throws InputError naming the file and JSON pointer (gltf_document.h,
// gltf_materials.h, gltf_textures.h, gltf_lights.h), and for a scene with no triangles to draw.
GltfDescription describe_gltf_scene(const std::filesystem::path& path);

// The load stage: the accessors and images decoded (gltf_geometry.h, gltf_textures.h), then the
// camera. `camera`: the name of a camera (or of the node that holds it) to look through; empty:
// the first camera of the scene's nodes, or, in a file without cameras, one that frames the meshes
// from +Z (noted). Throws InputError naming the file and JSON pointer (gltf_accessor.h,
// gltf_geometry.h, gltf_textures.h, gltf_cameras.h), or "--camera" for a name the file does not
// have. Scene::import_notes lists what was mapped and what was ignored.
Scene load_gltf_scene(GltfDescription description, const std::string& camera = "");

// Describes then loads into `scene`, for each glTF object (ObjectDescription::Source::Gltf; the
// others are skipped), the meshes of the node (its subtree, in the node's world transform in the
// file) or of the whole scene, with the file's materials (mapped as above, appended once per file
// however many objects import it, each object's primitives reading the UVs their material was
// mapped with: MappedMaterial) unless one is given; each note once per file. The file's lights
// and cameras are not imported (noted): the JSON scene has its own. `overrides` apply to the
// materials they select: by name first, then "#N", then "*"; a name or index the file does not have
// is an InputError naming `scene_file` and the override's key. The scene limits count these
// objects, vertices and materials with the scene's. Throws InputError naming `scene_file` and the
// key for a node the file does not have.
void import_objects(const std::vector<ObjectDescription>& objects, const std::string& scene_file,
                    Scene& scene);

}  // namespace lt::gltf
