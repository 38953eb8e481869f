#include "render/session.h"

namespace lt {

Image render_scene(const Scene& scene, const std::string& path_name, const std::string& variant,
                   int width, int height) {
  const PathInfo& info = find_path(path_name);
  const std::string v = resolve_variant(info, variant);
  RenderSession session(scene, width > 0 ? width : scene.width, height > 0 ? height : scene.height);
  auto path = session.build(info, v);
  path->frame();
  return path->result();
}

}  // namespace lt
