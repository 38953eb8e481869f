// `--lights default|none`, the one option every command that loads a scene shares: the commands
// register it here and hand SceneOptions to load_scene, which applies it (scene/default_lights.h).
#pragma once

#include <CLI/CLI.hpp>

#include "load/load_scene.h"

namespace lt::cli {

void add_lights_option(CLI::App* command, SceneOptions& options);

}  // namespace lt::cli
