// The animation a port is judged along (issue 26): a scene's camera and lights moved over N
// frames, as a game moves them. The GxModule test drives the exported module along it, and
// `ltrender sweep` measures every variant's error against the reference over it
// (docs/porting-to-the-wii.md has the table).
#pragma once

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace lt {

// How many frames the GxModule test and the table in docs/porting-to-the-wii.md use.
inline constexpr int kCameraPathFrames = 8;

// Frame k of `frames` (k = 0 is the scene as it is, unrounded): the eye orbits the target about the
// up axis (up to 70 degrees at the last frame), point lights orbit it the other way (up to 50
// degrees), directional lights turn with them, and every light's colour and translucency scale grow
// (up to x1.6 and x1.5). Every moved number is rounded to float, as a game holds it (the module's
// inputs are f32).
Scene scene_on_camera_path(const Scene& base, int k, int frames = kCameraPathFrames);

// v rounded to the nearest float, through a volatile: GCC 12's SLP vectoriser drops the float
// round trip of a dvec3's three components at -O2 and -O3 (dvec3(vec3(v)) in a loop comes back
// unrounded).
double rounded_to_float(double v);
glm::dvec3 rounded_to_float(const glm::dvec3& v);

}  // namespace lt
