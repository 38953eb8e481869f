// A scene ready to render at one size: the OSMesa context and the uploaded geometry that every
// path of that scene shares.
#pragma once

#include <memory>

#include "gl/context.h"
#include "gl/scene_geometry.h"
#include "image/image.h"
#include "paths/path.h"

namespace lt {

// At most 4096^2 pixels (image/image.h says why).
inline constexpr long long kMaxPixels = kMaxImagePixels;

// Throws InputError(file, where, ...) unless width x height is at least 1x1 and at most
// kMaxPixels pixels in all. `file`/`where` name what set the size: the scene's "image" key, or
// the options that override it.
void check_image_size(int width, int height, const std::string& file, const std::string& where);

class RenderSession {
 public:
  RenderSession(const Scene& scene, int width, int height)
      : scene_(scene),
        gl_(checked(scene, width, height), height),
        geometry_(scene, width, height) {}

  // Builds a path for this scene (variant already resolved).
  std::unique_ptr<Path> build(const PathInfo& path, const std::string& variant,
                              const PathOptions& options = {}) {
    return path.create(context(options), variant);
  }

  // What a path gets: the scene, this context and geometry, at this size.
  PathContext context(const PathOptions& options = {}) {
    return PathContext{scene_, gl_, geometry_, gl_.width(), gl_.height(), options};
  }

  const Scene& scene() const { return scene_; }
  gl::Context& gl() { return gl_; }
  gl::SceneGeometry& geometry() { return geometry_; }

 private:
  static int checked(const Scene& scene, int width, int height);

  const Scene& scene_;
  gl::Context gl_;
  gl::SceneGeometry geometry_;
};

// Throws InputError("--profile", ...) when a profile is given to a path that takes none.
void check_profile_option(const PathInfo& path, const std::string& profile);

// Renders one frame of `path_name` (with `variant`, empty for the default) at the scene's size
// unless width/height > 0 are given.
Image render_scene(const Scene& scene, const std::string& path_name, const std::string& variant,
                   int width = 0, int height = 0, const PathOptions& options = {});

}  // namespace lt
