#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cli/commands.h"
#include "cli/export_texture.h"
#include "cli/lights_option.h"
#include "core/error.h"
#include "core/fs.h"
#include "load/load_scene.h"
#include "render/camera_path.h"
#include "render/evaluate.h"
#include "render/session.h"

namespace lt::cli {

namespace {

// The paths that export (PathInfo::export_formats), as `each` words them, ", "-separated.
std::string exporters(const std::function<std::string(const PathInfo&)>& each,
                      const char* separator = ", ") {
  std::string out;
  for (const PathInfo& p : all_paths())
    if (!p.export_formats.empty()) out += (out.empty() ? "" : separator) + each(p);
  return out;
}

// "c: libogc C for the scene's frame (default); module: ...": every exporter's formats.
std::string formats_help(const PathInfo& p) {
  std::string out;
  for (const ExportFormat& f : p.export_formats)
    out +=
        (out.empty() ? "" : "; ") + f.name + ": " + f.summary + (out.empty() ? " (default)" : "");
  return out;
}

// "FILE.c or FILE.dff": the extensions the exports write, each once.
std::string outputs_help() {
  std::string out;
  for (const PathInfo& p : all_paths())
    for (const ExportFormat& f : p.export_formats)
      if ((out + " ").find("FILE" + f.extension + " ") == std::string::npos)
        out += (out.empty() ? "FILE" : " or FILE") + f.extension;
  return out;
}

// The path TARGET names, which must export: one line naming those that do otherwise.
const PathInfo& export_path(const std::string& target) {
  const std::string valid = exporters([](const PathInfo& p) { return p.name; });
  for (const PathInfo& p : all_paths()) {
    if (p.name != target) continue;
    if (p.export_formats.empty())
      throw InputError("export", target,
                       "path " + target + " exports nothing (valid: " + valid + ")");
    return p;
  }
  throw InputError("export", target, "unknown export target (valid: " + valid + ")");
}

// The index of --format in the path's formats; not given: the default, the first.
std::size_t export_format(const PathInfo& path, const CLI::Option& given, const std::string& name) {
  if (given.count() == 0) return 0;
  std::string valid;
  for (std::size_t i = 0; i < path.export_formats.size(); ++i) {
    if (path.export_formats[i].name == name) return i;
    valid += (valid.empty() ? "" : ", ") + path.export_formats[i].name;
  }
  throw InputError("export", "--format", name + ": unknown format (valid: " + valid + ")");
}

}  // namespace

// `ltrender export TARGET SCENE [--variant V] [--format F] -o FILE` (cli.md): the programs the
// path TARGET generates for the scene, written for a target that is not ltrender (gx.md §2: libogc
// C, a game's module, a Dolphin FIFO log). The path checks the options its format takes and
// builds the file; the command reads the scene, measures what the path asks and writes it.
Action add_export(CLI::App& app) {
  auto target = std::make_shared<std::string>();
  auto format = std::make_shared<std::string>();
  auto output = std::make_shared<std::string>();
  auto r = std::make_shared<ExportRequest>();
  auto scene_options = std::make_shared<SceneOptions>();
  auto* sub =
      app.add_subcommand("export", "Write a path's generated programs as code for the target");
  sub->add_option("TARGET", *target,
                  exporters([](const PathInfo& p) {
                    return p.name + " (" + p.export_target + ")";
                  }) + ", or texture (one image as a GX texture in a libogc TPL file)")
      ->required();
  sub->add_option("SCENE", r->scene_file,
                  "Scene file (JSON, .gltf or .glb); for texture, the image (PNG, EXR, JPEG)")
      ->required();
  auto texture = std::make_shared<TextureExportRequest>();
  sub->add_flag(
      "--mipmaps", texture->mipmaps,
      "texture: the whole mip chain down to 1x1, each level a 2x2 box filter of the last");
  sub->add_option("--rounding", texture->rounding,
                  "texture: nearest (default: each field's nearest expansion) or truncate "
                  "(gxtexconv's v >> (8 - bits))");
  sub->add_option("--tlut", texture->tlut,
                  "texture: the palette format of CI4, CI8, CI14X2: IA8, RGB565 (default), RGB5A3");
  sub->add_option("--variant", r->variant, exporters([](const PathInfo& p) {
                    return "The " + p.name + " variant (default " + p.variants.front().name + ")";
                  }));
  const CLI::Option* format_option =
      sub->add_option("--format", *format,
                      exporters(formats_help, "; ") +
                          "; texture: I4, I8, IA4, IA8, RGB565, RGB5A3, RGBA8, CI4, "
                          "CI8, CI14X2 or CMPR");
  sub->add_option("--width", r->width, "dff: frame width (default: the scene's)");
  sub->add_option("--height", r->height, "dff: frame height (default: the scene's)");
  sub->add_option("--program", r->program_file,
                  "dff: a gx program file drawn instead of the generated programs");
  sub->add_option("--frames", r->frames,
                  "dff: N frames along the camera path (the eye orbits 70 degrees, the lights 50 "
                  "the other way), one log; default 1, the scene as it is")
      ->check(CLI::Range(1, 64));
  sub->add_option("--light-range", r->light_range,
                  "D: no point light comes closer than D to a vertex it lights; the TEV scales "
                  "are chosen for it instead of from the visible vertices (the variant's "
                  ":light-range=D)");
  sub->add_option("-o,--output", *output, outputs_help())->required();
  add_lights_option(sub, *scene_options);
  return [=]() -> int {
    if (*target == "texture") {
      texture->image = r->scene_file;
      texture->format = *format;
      texture->format_given = format_option->count() > 0;
      texture->output = *output;
      return export_texture(*texture);
    }
    const PathInfo& info = export_path(*target);
    r->format = export_format(info, *format_option, *format);
    const std::string extension = info.export_formats[r->format].extension;
    if (fs::path(*output).extension() != extension)
      throw InputError(*output, "", "the exported file must end in " + extension);
    const std::string variant = info.export_variant(*r);
    const Scene scene = load_scene(r->scene_file, *scene_options);
    std::vector<fs::path> inputs = {r->scene_file};
    if (!r->program_file.empty()) inputs.push_back(r->program_file);
    for (const SceneObject& o : scene.objects) inputs.push_back(o.mesh_path);
    ensure_not_an_input(*output, inputs);
    ExportInput in{scene, variant, {}, [&] {
                     RenderSession session(scene, scene.width, scene.height);
                     const Image reference = render_reference(session);
                     auto path = session.build(info, variant);
                     path->frame();
                     return compare_with_reference(*path, reference).covered;
                   }};
    for (int k = 0; r->frames > 1 && k < r->frames; ++k)
      in.frames.push_back(scene_on_camera_path(scene, k, r->frames));
    write_text_file(*output, info.export_scene(*r, in));
    return 0;
  };
}

}  // namespace lt::cli
