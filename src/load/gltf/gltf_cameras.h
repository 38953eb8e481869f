// The camera of a whole glTF scene (glTF 2.0 §3.10): the one `--camera` names, else the first
// on a node of the scene, else one that frames the meshes.
#pragma once

#include <string>
#include <vector>

#include "load/gltf/gltf_description.h"

namespace lt::gltf {

// The camera `--camera` asks for: by name (of the camera or its node) first, so a camera named
// "2" stays reachable by its name, then by index. InputError("--camera", ...) listing the
// cameras there are when none matches.
const CameraInstance& chosen_camera(const Document& doc, const std::vector<CameraInstance>& cameras,
                                    const std::string& wanted);

// Looks through `inst`: the scene's camera, and its image width from the aspect ratio (noted).
void camera_from(const Document& doc, const CameraInstance& inst, Scene& scene);

// No camera in the file: look down -Z at the meshes' bounding box, from far enough away that
// its bounding sphere fits the default 40 degree view (noted).
void framing_camera(Scene& scene);

}  // namespace lt::gltf
