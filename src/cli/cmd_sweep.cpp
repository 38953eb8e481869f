// `ltrender sweep SCENE... [--path gx]`: every variant's error against the reference over the
// frames of the camera path (report/sweep.h says what the figures are), as a Markdown table on
// stdout: what docs/porting-to-the-wii.md's table of the moving camera is made with.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "core/error.h"
#include "paths/path.h"
#include "render/camera_path.h"
#include "report/sweep.h"

namespace lt::cli {

Action add_sweep(CLI::App& app) {
  auto o = std::make_shared<SweepOptions>();
  auto scenes = std::make_shared<std::vector<std::string>>();
  auto variants = std::make_shared<std::string>("all");
  auto* sub = app.add_subcommand(
      "sweep", "A path's variants against the reference along a moving camera and lights");
  sub->add_option("SCENE", *scenes, "Scene files")->required();
  sub->add_option("--path", o->path, "The path whose variants are measured (default gx)");
  sub->add_option("--variants", *variants, "all (default), default or story, as bench takes it")
      ->check(CLI::IsMember(variant_selections()));
  o->frames = kCameraPathFrames;
  sub->add_option("--frames", o->frames,
                  "Frames along the path (default 8: the GxModule test's; 1 is the scene as it is)")
      ->check(CLI::Range(1, 1000));
  sub->add_option("--light-range", o->light_range,
                  "gx: D, each variant measured again with :light-range=D (the TEV scales from "
                  "a declared bound: no point light closer than D to a vertex)");
  sub->add_option("--width", o->width, "Override the scene's width")->check(CLI::Range(1, 16384));
  sub->add_option("--height", o->height, "Override the scene's height")
      ->check(CLI::Range(1, 16384));
  return [o, scenes, variants]() -> int {
    if ((o->width > 0) != (o->height > 0))
      throw InputError("--width/--height", "", "give both, or neither");
    if (!o->light_range.empty()) {
      // The path's own variant parser says whether it has the axis and takes the value.
      const PathInfo& info = find_path(o->path);
      try {
        info.parse_variant(resolve_variant(info, "") + ":light-range=" + o->light_range);
      } catch (const InputError& e) {
        throw InputError(
            "--light-range", o->light_range,
            "path " + info.name + " takes no such :light-range= variant (" + e.what_only() + ")");
      }
    }
    o->variants = variant_selections().at(*variants);
    for (const std::string& s : *scenes) o->scenes.emplace_back(s);
    o->progress = [](const std::string& scene) { std::cerr << "sweep: " << scene << "\n"; };
    std::cout << sweep_markdown(run_sweep(*o));
    return 0;
  };
}

}  // namespace lt::cli
