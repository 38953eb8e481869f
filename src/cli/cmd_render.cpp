#include <memory>

#include "cli/commands.h"
#include "core/error.h"
#include "core/fs.h"
#include "image/image.h"
#include "render/session.h"

namespace lt::cli {

namespace {
struct RenderArgs {
  std::string scene, path, variant, output, program, camera, profile;
  int width = 0, height = 0;
};

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
  sub->add_option("--camera", a->camera,
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
    // The options' size, before the meshes are read when both are given; with one, the other
    // side is the scene's. Their error names the options, not the scene's `image` key.
    const char* const size_options = "--width/--height";
    if (a->width > 0 && a->height > 0) check_image_size(a->width, a->height, size_options, "");
    const Scene scene = load_scene(a->scene, SceneOptions{a->camera});
    if (a->width > 0 || a->height > 0) {
      check_image_size(a->width > 0 ? a->width : scene.width,
                       a->height > 0 ? a->height : scene.height, size_options, "");
    }
    std::vector<fs::path> inputs = {a->scene};
    if (!a->program.empty()) inputs.push_back(a->program);
    for (const SceneObject& o : scene.objects) inputs.push_back(o.mesh_path);
    ensure_not_an_input(a->output, inputs);
    if (info.refusal) {
      const std::string why = info.refusal(scene, variant);
      if (!why.empty()) throw InputError("--variant", variant, info.name + ": " + why);
    }
    const Image img = render_scene(scene, info.name, variant, a->width, a->height,
                                   PathOptions{a->program, a->profile});
    write_image(a->output, img);
    return 0;
  };
}

}  // namespace lt::cli
