#include "render/evaluate.h"

namespace lt {

Image render_reference(RenderSession& session) {
  const PathInfo& reference = path_with_role(PathRole::GroundTruth);
  auto path = session.build(reference, reference.variants.front().name);
  path->frame();
  return path->result();
}

TestEncoding test_encoding(const Path& path) {
  return path.float_output() ? TestEncoding::kFloat : TestEncoding::kUnorm8;
}

Comparison compare_with_reference(Path& path, const Image& reference) {
  return compare_images(path.result(), reference, test_encoding(path));
}

}  // namespace lt
