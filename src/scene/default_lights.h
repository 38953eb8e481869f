// The default light rig (docs/spec/scene-format.md, "Default lights"): what lights a scene that
// has no light and no ambient light, which would otherwise render black with nothing said. Most
// assets made for engines carry no lights (KHR_lights_punctual is rare).
#pragma once

#include <string>

#include "scene/scene.h"

namespace lt {

// How the rig's back light meets the view: it travels towards the camera, from behind the
// object and this far above the view axis (tan of the angle, ~14 degrees), so the translucent
// glow sits around the silhouette's centre and the lobe peaks on it.
inline constexpr double kBackLightRise = 0.25;
// The fill comes from the camera's side, up and to the left, at this fraction of the back light.
inline constexpr double kFillIntensity = 0.5;

// No light and no ambient light: nothing would be lit.
bool renders_unlit(const Scene& scene);

// Appends the rig, derived from the scene's camera (so the back light is behind the object as
// seen from it, whatever the file's orientation): a white directional back light (colour 1,
// translucency_scale 1) travelling towards the camera from behind, and a white directional
// fill (colour kFillIntensity) from up-left of the camera. Returns the description `info` and
// the warning give.
std::string add_default_lights(Scene& scene);

}  // namespace lt
