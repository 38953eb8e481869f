// The CPU paths' packed G-buffer (paths/common/gbuffer.h, issue 39): coverage and material share
// the position target's alpha (material + 1 over a target cleared to 0), and only the targets a
// scene's materials read are drawn. The material of each pixel is held to what the glsl path
// covers with each object drawn alone, on a scene whose objects do not overlap on screen.
#include <gtest/gtest.h>

#include "load/load_scene.h"
#include "paths/common/gbuffer.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

constexpr int kLayoutWidth = 160, kLayoutHeight = 120;

Scene layout_scene(const char* name) {
  return load_scene(test::source_dir() / "scenes" / name);
}

TEST(GBufferLayout, EachPixelsMaterialIsTheOneObjectCoveringIt) {
  Scene scene = layout_scene("coloured_cubes.json");
  ASSERT_EQ(scene.objects.size(), 2u);
  // Materials past the first few, so the index carried as a float + 1 is more than 0 or 1.
  for (int i = 0; i < 7; ++i) scene.materials.push_back(scene.materials[i % 2]);
  scene.objects[0].material = 8;
  scene.objects[1].material = 5;

  RenderSession session(scene, kLayoutWidth, kLayoutHeight);
  const std::vector<int> material = material_per_pixel(session.context());
  ASSERT_EQ(material.size(), static_cast<size_t>(kLayoutWidth) * kLayoutHeight);

  std::vector<int> expected(material.size(), -1);
  for (const SceneObject& object : scene.objects) {
    Scene alone = scene;
    alone.objects = {object};
    const Image glsl = render_scene(alone, "glsl", resolve_variant(find_path("glsl"), ""),
                                    kLayoutWidth, kLayoutHeight);
    size_t covered = 0;
    for (int y = 0; y < kLayoutHeight; ++y) {
      for (int x = 0; x < kLayoutWidth; ++x) {
        if (glsl.at(x, y)[3] <= 0) continue;
        int& e = expected[static_cast<size_t>(y) * kLayoutWidth + x];
        ASSERT_EQ(e, -1) << "the objects overlap at " << x << "," << y;
        e = object.material;
        ++covered;
      }
    }
    EXPECT_GT(covered, 0u);
  }
  size_t differ = 0;
  for (size_t i = 0; i < material.size(); ++i) differ += material[i] != expected[i];
  EXPECT_EQ(differ, 0u);
}

// The stage line `info` prints names the targets the G-buffer drew.
std::string layout_of(const char* scene_name) {
  const Scene scene = layout_scene(scene_name);
  RenderSession session(scene, kLayoutWidth, kLayoutHeight);
  return GBuffer(session.context(), "the layout test").stages().at(0).name;
}

TEST(GBufferLayout, ASceneWithoutMapsOrVertexThicknessDrawsTwoTargets) {
  EXPECT_EQ(layout_of("coloured_cubes.json"),
            "G-buffer: 2 x RGBA32F (position + material, normal)");
}

TEST(GBufferLayout, VertexThicknessOrAMapAddsTheThirdTarget) {
  EXPECT_EQ(layout_of("teapot_vertex.json"),
            "G-buffer: 3 x RGBA32F (position + material, normal, vertex thickness)");
  EXPECT_EQ(layout_of("albedo_checker.json"),
            "G-buffer: 3 x RGBA32F (position + material, normal + map u, map v)");
}

}  // namespace
}  // namespace lt
