#include "paths/gx/gx_export.h"

#include "core/error.h"
#include "paths/gx/c_exporter.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_budget.h"
#include "paths/gx/module/module_exporter.h"

namespace lt::gx {

namespace {

// gx_export_formats() in this order.
enum Format : std::size_t { kC, kModule, kDff };

// `--format dff --frames N`: the scene along the first N frames of the camera path (the module
// tests' animation), each frame its own camera, lights and generated programs (the module's for
// that frame: GxModule), as one log Dolphin dumps every frame of (for_dolphin_animation).
std::vector<std::uint8_t> animation_fifo_log(const Scene& base, const std::vector<Scene>& scenes,
                                             const GxVariant& v, FrameSize size) {
  std::vector<ScenePrograms> programs;
  for (const Scene& s : scenes) programs.push_back(scene_programs_for(s, v, ""));
  std::vector<fifo::FrameInput> inputs;
  for (size_t k = 0; k < scenes.size(); ++k) inputs.push_back({v, &programs[k], &scenes[k]});
  return fifo::write_fifo_log(fifo::for_dolphin_animation(fifo::record_frames(base, inputs, size)));
}

// `--format dff`: the frame as the console receives it, at the scene's size or --width x
// --height (gx/fifo/).
std::string fifo_log_file(const PathInfo& gx, const ExportRequest& r, const ExportInput& in) {
  const FrameSize size{r.width ? r.width : in.scene.width, r.height ? r.height : in.scene.height};
  fifo::check_frame_size(size, r.scene_file, r.width ? "--width" : "width",
                         r.height ? "--height" : "height");
  const std::vector<std::uint8_t> bytes =
      r.frames > 1 ? animation_fifo_log(in.scene, in.frames, parse_gx_variant(in.variant), size)
                   : gx.fifo_log(in.scene, in.variant, PathOptions{r.program_file, ""}, size.width,
                                 size.height);
  return std::string(bytes.begin(), bytes.end());
}

}  // namespace

std::vector<ExportFormat> gx_export_formats() {
  return {{"c", ".c", "libogc C for the scene's frame"},
          {"module", ".c", "libogc C a game runs every frame, camera and lights as inputs"},
          {"dff", ".dff", "the frame as a Dolphin FIFO log"}};
}

std::string gx_export_variant(const PathInfo& gx, const ExportRequest& r) {
  if (r.format != kDff &&
      (r.width != 0 || r.height != 0 || !r.program_file.empty() || r.frames != 1))
    throw InputError("export",
                     !r.program_file.empty() ? "--program"
                     : r.frames != 1         ? "--frames"
                                             : "--width",
                     "--width, --height, --program and --frames are for --format dff");
  if (r.frames != 1 && !r.program_file.empty())
    throw InputError("export", "--frames",
                     "a program file is one frame's state: --frames draws the generated "
                     "programs of each frame");
  // --light-range D is the variant's :light-range=D axis (gx_variant.h), which checks D.
  if (r.light_range.empty()) return resolve_variant(gx, r.variant);
  return resolve_variant(gx, (r.variant.empty() ? gx.variants.front().name : r.variant) +
                                 ":light-range=" + r.light_range);
}

// C: the generated programs with the error of exactly that program against the reference at
// the scene's size and the budget; module: C a game runs every frame, its camera and lights as
// inputs (paths/gx/module/); dff: the FIFO log.
std::string gx_export_scene(const PathInfo& gx, const ExportRequest& r, const ExportInput& in) {
  if (r.format == kDff) return fifo_log_file(gx, r, in);
  const GxVariant v = parse_gx_variant(in.variant);
  // The C declares the variant's storage and :draw= (plan_emitter.cpp vertex_format); the
  // module refuses them (module_exporter.h).
  if (r.format == kModule) return export_module(in.scene, v, r.scene_file);
  const ScenePrograms programs = scene_programs_for(in.scene, v, "");
  ExportFigures f;
  f.scene = r.scene_file;
  f.variant = in.variant;
  f.width = in.scene.width;
  f.height = in.scene.height;
  f.error = in.error();
  f.budget = budget::to_text(gx_budget_scene(in.scene, in.variant, "wii-tev"));
  return export_c(programs, f);
}

}  // namespace lt::gx
