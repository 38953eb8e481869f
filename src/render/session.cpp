#include "render/session.h"

#include "core/error.h"
#include "render/evaluate.h"

namespace lt {

void check_image_size(int width, int height, const std::string& file, const std::string& where) {
  const long long pixels = static_cast<long long>(width) * height;
  if (width >= 1 && height >= 1 && pixels <= kMaxPixels) return;
  // The limit is on the pixel count, not on each side (8192x2048 is fine): say it that way.
  std::string what = std::to_string(width);
  what.append("x")
      .append(std::to_string(height))
      .append(" is ")
      .append(std::to_string(pixels))
      .append(" pixels, over the limit of ")
      .append(std::to_string(kMaxPixels))
      .append(" (4096^2; the reference needs ~100 bytes a pixel)");
  throw InputError(file, where, what);
}

int RenderSession::checked(const Scene& scene, int width, int height) {
  check_image_size(width, height, scene.file.string(), "image");
  return width;
}

void check_profile_option(const PathInfo& path, const std::string& profile) {
  if (!profile.empty() && !path.takes_profile)
    throw InputError("--profile", profile,
                     "path " + path.name + " takes no profile (the arbfp path does)");
}

Image render_scene(const Scene& scene, const std::string& path_name, const std::string& variant,
                   int width, int height, const PathOptions& options) {
  const PathInfo& info = find_path(path_name);
  const std::string v = resolve_variant(info, variant);
  if (!options.program_file.empty() && !info.takes_program_file)
    throw InputError("--program", options.program_file,
                     "path " + info.name + " takes no program file (the gx path does)");
  check_profile_option(info, options.profile);
  RenderSession session(scene, width > 0 ? width : scene.width, height > 0 ? height : scene.height);
  return render_frame(session, info, v, options);
}

}  // namespace lt
