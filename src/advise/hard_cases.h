// The hard cases of docs/spec/model.md (scenes/hard/) a material can reach: those that depend on
// the mesh, the camera or the lights are reachable by any material; those of a material
// parameter only by a material whose parameter lies on the hard side (p >= 128 reaches
// power_128, a negative d distortion_negative, ...). `advise` renders every candidate it would
// pick on them, so that a pick never trades a NaN for an ALU.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace lt::advise {

struct HardCase {
  std::filesystem::path file;  // scenes/hard/NAME.json of the source tree
  std::string reached_by;      // why this material reaches it ("p = 0", "any mesh")
};

std::vector<HardCase> reachable_hard_cases(const Scene& scene, const Material& material);

}  // namespace lt::advise
