#include <fstream>

#include "cli/commands.h"
#include "cli/lights_option.h"
#include "core/error.h"
#include "core/fs.h"
#include "load/load_scene.h"
#include "paths/gx/c_exporter.h"
#include "paths/gx/fifo/frame_recording.h"
#include "paths/gx/gx_budget.h"
#include "paths/gx/module/module_exporter.h"
#include "render/camera_path.h"
#include "render/evaluate.h"
#include "render/session.h"

namespace lt::cli {

namespace {

// `--format dff --frames N`: the scene along the first N frames of the camera path
// (render/camera_path.h, the module tests' animation), each frame its own camera, lights and
// generated programs (the module's for that frame: GxModule), as one log Dolphin dumps every
// frame of (for_dolphin_animation).
std::vector<std::uint8_t> animation_fifo_log(const Scene& base, const std::string& variant,
                                             int frames, gx::fifo::FrameSize size) {
  const gx::GxVariant v = gx::parse_gx_variant(variant);
  std::vector<Scene> scenes;
  for (int k = 0; k < frames; ++k) scenes.push_back(scene_on_camera_path(base, k, frames));
  std::vector<gx::ScenePrograms> programs;
  for (const Scene& s : scenes) programs.push_back(gx::scene_programs_for(s, v, ""));
  std::vector<gx::fifo::FrameInput> inputs;
  for (size_t k = 0; k < scenes.size(); ++k) inputs.push_back({v, &programs[k], &scenes[k]});
  return gx::fifo::write_fifo_log(
      gx::fifo::for_dolphin_animation(gx::fifo::record_frames(base, inputs, size)));
}

}  // namespace

// `ltrender export gx SCENE [--variant V] [--format c|module|dff] -o FILE` (gx.md §2): the
// generated GX programs as C, with the error of exactly that program measured against the
// reference at the scene's size; (`--format module`) as C a game runs every frame, its camera
// and lights as inputs (paths/gx/module/); or (`--format dff`) the frame as the console receives
// it, a Dolphin FIFO log (paths/gx/fifo/) at the scene's size or --width x --height.
Action add_export(CLI::App& app) {
  auto target = std::make_shared<std::string>();
  auto scene_path = std::make_shared<std::string>();
  auto variant = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>("c");
  auto width = std::make_shared<int>(0);
  auto height = std::make_shared<int>(0);
  auto program = std::make_shared<std::string>();
  auto light_range = std::make_shared<std::string>();
  auto frames = std::make_shared<int>(1);
  auto scene_options = std::make_shared<SceneOptions>();
  auto* sub =
      app.add_subcommand("export", "Write a path's generated programs as code for the target");
  sub->add_option("TARGET", *target, "gx (libogc C for the Wii / GameCube)")->required();
  sub->add_option("SCENE", *scene_path, "Scene file (JSON, .gltf or .glb)")->required();
  sub->add_option("--variant", *variant, "The gx variant (default t=vertex)");
  sub->add_option("--format", *format,
                  "c: libogc C for the scene's frame (default); module: libogc C a game runs every "
                  "frame, camera and lights as inputs; dff: the frame as a Dolphin FIFO log");
  sub->add_option("--width", *width, "dff: frame width (default: the scene's)");
  sub->add_option("--height", *height, "dff: frame height (default: the scene's)");
  sub->add_option("--program", *program,
                  "dff: a gx program file drawn instead of the generated programs");
  sub->add_option("--frames", *frames,
                  "dff: N frames along the camera path (the eye orbits 70 degrees, the lights 50 "
                  "the other way), one log; default 1, the scene as it is")
      ->check(CLI::Range(1, 64));
  sub->add_option("--light-range", *light_range,
                  "D: no point light comes closer than D to a vertex it lights; the TEV scales "
                  "are chosen for it instead of from the visible vertices (the variant's "
                  ":light-range=D)");
  sub->add_option("-o,--output", *output, "FILE.c or FILE.dff")->required();
  add_lights_option(sub, *scene_options);
  return [=]() -> int {
    if (*target != "gx") throw InputError("export", *target, "unknown export target (valid: gx)");
    if (*format != "c" && *format != "module" && *format != "dff")
      throw InputError("export", "--format", *format + ": unknown format (valid: c, module, dff)");
    const std::string extension = *format == "dff" ? ".dff" : ".c";
    if (fs::path(*output).extension() != extension)
      throw InputError(*output, "", "the exported file must end in " + extension);
    if (*format != "dff" && (*width != 0 || *height != 0 || !program->empty() || *frames != 1))
      throw InputError("export",
                       !program->empty() ? "--program"
                       : *frames != 1    ? "--frames"
                                         : "--width",
                       "--width, --height, --program and --frames are for --format dff");
    if (*frames != 1 && !program->empty())
      throw InputError("export", "--frames",
                       "a program file is one frame's state: --frames draws the generated "
                       "programs of each frame");
    const PathInfo& info = find_path("gx");
    // --light-range D is the variant's :light-range=D axis (gx_variant.h), which checks D.
    const std::string v = resolve_variant(
        info, light_range->empty() ? *variant
                                   : (variant->empty() ? info.variants.front().name : *variant) +
                                         ":light-range=" + *light_range);
    const Scene scene = load_scene(*scene_path, *scene_options);
    std::vector<fs::path> inputs = {*scene_path};
    if (!program->empty()) inputs.push_back(*program);
    for (const SceneObject& o : scene.objects) inputs.push_back(o.mesh_path);
    ensure_not_an_input(*output, inputs);
    if (*format == "dff") {
      const gx::fifo::FrameSize size{*width ? *width : scene.width,
                                     *height ? *height : scene.height};
      gx::fifo::check_frame_size(size, *scene_path, *width ? "--width" : "width",
                                 *height ? "--height" : "height");
      const std::vector<std::uint8_t> bytes =
          *frames > 1 ? animation_fifo_log(scene, v, *frames, size)
                      : info.fifo_log(scene, v, PathOptions{*program, ""}, size.width, size.height);
      write_atomically(*output, [&](const fs::path& tmp) {
        std::ofstream out(tmp, std::ios::binary);
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
        if (!out) throw InputError(*output, "", "cannot write");
      });
      return 0;
    }
    const gx::GxVariant gv = gx::parse_gx_variant(v);
    if (*format == "module") {
      write_text_file(*output, gx::export_module(scene, gv, *scene_path));
      return 0;
    }
    const gx::ScenePrograms programs = gx::scene_programs_for(scene, gv, "");
    gx::ExportFigures f;
    f.scene = *scene_path;
    f.variant = v;
    f.width = scene.width;
    f.height = scene.height;
    {
      RenderSession session(scene, scene.width, scene.height);
      const Image reference = render_reference(session);
      auto gxp = session.build(info, v);
      gxp->frame();
      f.error = compare_with_reference(*gxp, reference).covered;
    }
    f.budget = budget::to_text(gx::gx_budget_scene(scene, v, "wii-tev"));
    write_text_file(*output, gx::export_c(programs, f));
    return 0;
  };
}

}  // namespace lt::cli
