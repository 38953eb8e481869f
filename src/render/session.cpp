#include "render/session.h"

#include "core/error.h"

namespace lt {

int RenderSession::checked(const Scene& scene, int width, int height) {
  if (width < 1 || height < 1 || static_cast<long long>(width) * height > kMaxPixels) {
    throw InputError(scene.file.string(), "image",
                     std::to_string(width) + "x" + std::to_string(height) +
                         " is out of range (at most 4096 x 4096 pixels)");
  }
  return width;
}

Image render_scene(const Scene& scene, const std::string& path_name, const std::string& variant,
                   int width, int height, const PathOptions& options) {
  const PathInfo& info = find_path(path_name);
  const std::string v = resolve_variant(info, variant);
  if (!options.program_file.empty() && !info.takes_program_file)
    throw InputError("--program", options.program_file,
                     "path " + info.name + " takes no program file (the gx path does)");
  RenderSession session(scene, width > 0 ? width : scene.width, height > 0 ? height : scene.height);
  auto path = session.build(info, v, options);
  path->frame();
  return path->result();
}

}  // namespace lt
