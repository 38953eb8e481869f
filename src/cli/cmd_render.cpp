#include <memory>

#include "cli/commands.h"
#include "cli/lights_option.h"
#include "cli/threads_option.h"
#include "core/error.h"
#include "core/file_name.h"
#include "core/fs.h"
#include "image/image.h"
#include "judge/dolphin_player.h"
#include "load/load_scene.h"
#include "render/session.h"

namespace lt::cli {

namespace {
struct RenderArgs {
  std::string scene, path, variant, output, program, profile;
  SceneOptions scene_options;  // --camera, --lights
  int width = 0, height = 0;
  std::string via, keep_fifo_log;  // --via dolphin
  double dolphin_deadline = judge::DolphinOptions{}.deadline_seconds;
};

// --via dolphin, what can be checked before the scene is read: Dolphin's frame is 8-bit, the
// log kept is a .dff, and the path encodes a FIFO log.
void check_via_dolphin(const RenderArgs& a, const PathInfo& info) {
  if (lower_extension(a.output) != ".png")
    throw InputError(a.output, "", "--via dolphin writes Dolphin's 8-bit frame: use a .png");
  if (!a.keep_fifo_log.empty() && lower_extension(a.keep_fifo_log) != ".dff")
    throw InputError(a.keep_fifo_log, "", "--keep-fifo-log writes a Dolphin FIFO log: use a .dff");
  if (info.writes_fifo_log) return;
  std::string with;
  for (const PathInfo& p : all_paths())
    if (p.writes_fifo_log) with += (with.empty() ? "" : ", ") + p.name;
  throw InputError("--via dolphin", "",
                   "path " + info.name + " models no console (" +
                       (with.empty() ? std::string("no path in this build has a FIFO log")
                                     : "only " + with + " has a FIFO log") +
                       ")");
}

// Dolphin scales a dump to 4:3 (judge/dolphin_player.h): any other size would come back
// resampled, not as the console's pixels.
void check_dolphin_size(int width, int height, const std::string& file, const std::string& where) {
  if (judge::dumped_unscaled(width, height)) return;
  throw InputError(file, where,
                   "--via dolphin: Dolphin scales its frame dump to 4:3, so a " +
                       std::to_string(width) + "x" + std::to_string(height) +
                       " frame would come back resampled; use a 4:3 size whose width is a "
                       "multiple of 16 (320x240, 640x480)");
}

// The path's frame as a FIFO log, played by Dolphin; its last dump is the frame (the last
// frame of a log is never dumped, every dump shows the same frame).
Image render_via_dolphin(const RenderArgs& a, const PathInfo& info, const Scene& scene,
                         const std::string& variant, int width, int height) {
  const std::vector<std::uint8_t> log =
      info.fifo_log(scene, variant, PathOptions{a.program, a.profile}, width, height);
  judge::DolphinOptions options;
  options.deadline_seconds = a.dolphin_deadline;
  std::vector<Image> frames;
  if (!a.keep_fifo_log.empty()) {
    write_binary_file(a.keep_fifo_log, log);
    frames = judge::play_fifo_log(fs::path(a.keep_fifo_log), options);
  } else {
    frames = judge::play_fifo_log(log, options);
  }
  const Image& last = frames.back();
  if (last.width != width || last.height != height) {
    throw InputError("dolphin", "",
                     "dumped a " + std::to_string(last.width) + "x" + std::to_string(last.height) +
                         " frame for a " + std::to_string(width) + "x" + std::to_string(height) +
                         " FIFO log");
  }
  return last;
}

std::string path_help() {
  std::string s = "Paths and their variants (the first is the default):\n";
  for (const PathInfo& p : all_paths()) {
    s += "  " + p.name + ": " + p.summary + "\n";
    for (const VariantInfo& v : p.variants)
      s += "      --variant " + v.name + "  " + v.summary + "\n";
  }
  return s;
}
}  // namespace

Action add_render(CLI::App& app) {
  auto a = std::make_shared<RenderArgs>();
  auto* sub = app.add_subcommand("render", "Render a scene through one path");
  sub->add_option("SCENE", a->scene, "Scene file (JSON, .gltf or .glb)")->required();
  sub->add_option("--path", a->path, "reference | glsl | flat | ...")->required();
  sub->add_option("--variant", a->variant, "The path's approximation (see below)");
  sub->add_option("--width", a->width, "Override the scene's width")->check(CLI::Range(1, 16384));
  sub->add_option("--height", a->height, "Override the scene's height")
      ->check(CLI::Range(1, 16384));
  add_lights_option(sub, a->scene_options);
  add_threads_option(sub);
  sub->add_option("--camera", a->scene_options.camera,
                  "glTF scenes: the camera to look through, by its name or its node's, or by "
                  "its index '#N' (or N) for /cameras/N; a name wins over an index")
      ->type_name("NAME|#N");
  sub->add_option("-o,--output", a->output, "OUT.png (8-bit) or OUT.exr (float, A = coverage)")
      ->required();
  sub->add_option("--program", a->program,
                  "gx: a program file of libogc calls that replaces the generated programs "
                  "(e.g. one written by `ltrender export gx`)");
  sub->add_option("--profile", a->profile,
                  "arbfp: a profile the programs must fit (ps_2_0, ps_2_x, arbfp1-min, vs_2_0, "
                  "arbvp1-min); a material over it is drawn in additive passes that each fit");
  auto* via = sub->add_option("--via", a->via,
                              "dolphin: encode the path's frame as a FIFO log, play it in "
                              "Dolphin's software renderer and write Dolphin's frame "
                              "(docs/dolphin-judge.md)")
                  ->check(CLI::IsMember({"dolphin"}));
  sub->add_option("--keep-fifo-log", a->keep_fifo_log,
                  "With --via dolphin: also write the FIFO log Dolphin played (FILE.dff)")
      ->needs(via);
  sub->add_option("--dolphin-deadline", a->dolphin_deadline,
                  "With --via dolphin: seconds Dolphin may take, its X server's start included "
                  "(default 60)")
      ->check(FiniteRange(0.1, 3600.0))
      ->needs(via);
  sub->footer(path_help());
  return [a]() -> int {
    // Validate everything cheap before the scene's meshes are read.
    const PathInfo& info = find_path(a->path);
    const std::string variant = resolve_variant(info, a->variant);
    check_output_extension(a->output);
    if (!a->program.empty() && !info.takes_program_file)
      throw InputError("--program", a->program,
                       "path " + info.name + " takes no program file (the gx path does)");
    check_profile_option(info, a->profile);
    const bool via_dolphin = !a->via.empty();
    if (via_dolphin) check_via_dolphin(*a, info);
    // The options' size, before the meshes are read when both are given; with one, the other
    // side is the scene's. Their error names the options, not the scene's `image` key.
    const char* const size_options = "--width/--height";
    if (a->width > 0 && a->height > 0) check_image_size(a->width, a->height, size_options, "");
    if (via_dolphin && a->width > 0 && a->height > 0)
      check_dolphin_size(a->width, a->height, size_options, "");
    const Scene scene = load_scene(a->scene, a->scene_options);
    if (a->width > 0 || a->height > 0) {
      check_image_size(a->width > 0 ? a->width : scene.width,
                       a->height > 0 ? a->height : scene.height, size_options, "");
    }
    const int width = a->width > 0 ? a->width : scene.width;
    const int height = a->height > 0 ? a->height : scene.height;
    const bool size_given = a->width > 0 || a->height > 0;
    if (via_dolphin) {
      check_dolphin_size(width, height, size_given ? size_options : a->scene,
                         size_given ? "" : "image");
    }
    std::vector<fs::path> inputs = {a->scene};
    if (!a->program.empty()) inputs.push_back(a->program);
    for (const SceneObject& o : scene.objects) inputs.push_back(o.mesh_path);
    ensure_not_an_input(a->output, inputs);
    if (!a->keep_fifo_log.empty()) ensure_not_an_input(a->keep_fifo_log, inputs);
    const std::string why = info.refusal(scene, variant);
    if (!why.empty()) throw InputError("--variant", variant, info.name + ": " + why);
    const Image img = via_dolphin ? render_via_dolphin(*a, info, scene, variant, width, height)
                                  : render_scene(scene, info.name, variant, a->width, a->height,
                                                 PathOptions{a->program, a->profile});
    write_image(a->output, img);
    return 0;
  };
}

}  // namespace lt::cli
