#include "cli/lights_option.h"

namespace lt::cli {

void add_lights_option(CLI::App* command, SceneOptions& options) {
  command
      ->add_option_function<std::string>(
          "--lights",
          [&options](const std::string& value) { options.default_lights = value == "default"; },
          "default: a scene with no light and no ambient_light gets the default rig (a back "
          "light behind the object as the camera sees it, and a front fill; one warning line); "
          "none: it renders unlit")
      ->check(CLI::IsMember({"default", "none"}));
}

}  // namespace lt::cli
