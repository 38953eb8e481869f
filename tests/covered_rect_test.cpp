// SceneGeometry::covered_rect (gl/scene_geometry.h), the pixels the CPU paths' G-buffer clears
// and reads back (issue 39): every pixel the glsl path covers (its float image's alpha, drawn
// on the whole target) lies inside it, on every demo scene; it is smaller than the image where
// the objects fill part of it; and a camera with geometry behind it gets the whole viewport.
#include <gtest/gtest.h>

#include "load/load_scene.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

constexpr int kWidth = 160, kHeight = 120;

class CoveredRect : public ::testing::TestWithParam<std::string> {};

TEST_P(CoveredRect, HoldsEveryPixelTheGlslPathCovers) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  RenderSession session(scene, kWidth, kHeight);
  const gl::PixelRect rect = session.geometry().covered_rect();
  const Image glsl =
      render_scene(scene, "glsl", resolve_variant(find_path("glsl"), ""), kWidth, kHeight);
  size_t covered = 0, outside = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      if (glsl.at(x, y)[3] <= 0) continue;
      ++covered;
      outside += !rect.contains(x, kHeight - 1 - y);  // GL's rows count from the bottom
    }
  }
  EXPECT_GT(covered, 0u);
  EXPECT_EQ(outside, 0u) << "rect " << rect.x << "," << rect.y << " " << rect.width << "x"
                         << rect.height;
}

INSTANTIATE_TEST_SUITE_P(Demo, CoveredRect, ::testing::ValuesIn(test::json_files("scenes")),
                         [](const auto& info) { return test::scene_param_name(info.param); });

TEST(CoveredRectBound, IsSmallerThanTheImageWhereTheObjectsFillPartOfIt) {
  const Scene scene = load_scene(test::source_dir() / "scenes/debian_box_textured.json");
  RenderSession session(scene, kWidth, kHeight);
  const gl::PixelRect rect = session.geometry().covered_rect();
  EXPECT_LT(static_cast<long>(rect.width) * rect.height, static_cast<long>(kWidth) * kHeight);
}

// The eye at the sphere's centre: vertices all around it, some behind, where a projection
// bounds nothing.
TEST(CoveredRectBound, GeometryBehindTheEyeGivesTheWholeViewport) {
  Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  scene.camera.target = scene.camera.target - scene.camera.eye;
  scene.camera.eye = glm::dvec3(0);
  RenderSession session(scene, kWidth, kHeight);
  const gl::PixelRect rect = session.geometry().covered_rect();
  EXPECT_EQ(rect.x, 0);
  EXPECT_EQ(rect.y, 0);
  EXPECT_EQ(rect.width, kWidth);
  EXPECT_EQ(rect.height, kHeight);
}

}  // namespace
}  // namespace lt
