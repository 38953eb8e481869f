#include "render/evaluate.h"

#include "core/error.h"

namespace lt {

Image render_frame(RenderSession& session, const PathInfo& path, const std::string& variant,
                   const PathOptions& options) {
  auto built = session.build(path, variant, options);
  built->frame();
  return built->result();
}

Image render_reference(RenderSession& session) {
  const PathInfo& reference = path_with_role(PathRole::GroundTruth);
  return render_frame(session, reference, reference.variants.front().name);
}

TestEncoding test_encoding(const Path& path) {
  return path.float_output() ? TestEncoding::kFloat : TestEncoding::kUnorm8;
}

Comparison compare_with_reference(Path& path, const Image& reference) {
  return compare_with_reference(path.result(), test_encoding(path), reference);
}

Comparison compare_with_reference(const Image& render, TestEncoding encoding,
                                  const Image& reference) {
  return compare_images(render, reference, encoding, TestEncoding::kFloat, Coverage::kBoth);
}

Comparison compare_with_golden(const Image& render, Image golden) {
  LT_CHECK(golden.width == render.width && golden.height == render.height,
           "a golden of another size is the caller's to report");
  for (size_t i = 0; i < golden.pixel_count(); ++i) golden.rgba[i * 4 + 3] = render.rgba[i * 4 + 3];
  return compare_images(render, golden, TestEncoding::kUnorm8, TestEncoding::kUnorm8);
}

}  // namespace lt
