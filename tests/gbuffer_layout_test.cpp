// The CPU paths' packed G-buffer (paths/common/gbuffer.h, issue 39): coverage and material share
// the position target's alpha (material + 1 over a target cleared to 0), and only the targets a
// scene's materials read are drawn. The material of each pixel is held to what the glsl path
// covers with each object drawn alone, on a scene whose objects do not overlap on screen; a grey
// vertex thickness in one channel to the same in three.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>

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

TEST(GBufferLayout, AGreyVertexThicknessRidesInTheNormalTarget) {
  EXPECT_EQ(layout_of("teapot_vertex.json"),
            "G-buffer: 2 x RGBA32F (position + material, normal + grey vertex thickness)");
}

TEST(GBufferLayout, AMapAddsTheThirdTarget) {
  EXPECT_EQ(layout_of("albedo_checker.json"),
            "G-buffer: 3 x RGBA32F (position + material, normal + map u, map v)");
}

// Every covered pixel's lanes as shade_covered hands them out, in order (one worker), as bits.
std::vector<uint32_t> gathered_lanes(const GBuffer& g) {
  std::vector<uint32_t> lanes;
  auto keep = [&](const float* v, size_t n) {
    for (size_t i = 0; i < n; ++i) lanes.push_back(std::bit_cast<uint32_t>(v[i]));
  };
  Image image;
  g.shade_covered(image, glm::dvec3(0), [&](const PixelRun& run, ShadedRun& shaded, unsigned) {
    lanes.push_back(static_cast<uint32_t>(run.material));
    for (int c = 0; c < 3; ++c) {
      keep(run.position[c], run.count);
      keep(run.normal[c], run.count);
      keep(run.thickness[c], run.count);
    }
    for (int c = 0; c < 2; ++c) keep(run.uv[c], run.count);
    for (auto& channel : shaded.rgb) std::fill_n(channel, kPixelRunCapacity, 0.0f);
  });
  return lanes;
}

// The grey thickness in one channel is the bits its three channels held: red, green and blue of
// a grey are interpolated by one computation (gbuffer_layout.h counts on it).
TEST(GBufferLayout, OneChannelOfGreyThicknessIsItsThreeChannelsToTheBit) {
  worker_threads_setting() = 1;
  for (const char* name : {"baked_blob.json", "teapot_vertex.json", "thin_vs_thick.json"}) {
    const Scene scene = layout_scene(name);
    RenderSession session(scene, kLayoutWidth, kLayoutHeight);
    GBuffer one(session.context(), "the layout test", GreyThickness::OneChannel);
    GBuffer three(session.context(), "the layout test", GreyThickness::ThreeChannels);
    ASSERT_NE(one.stages().at(0).name, three.stages().at(0).name) << name;
    one.rasterise();
    three.rasterise();
    const std::vector<uint32_t> a = gathered_lanes(one), b = gathered_lanes(three);
    EXPECT_GT(a.size(), 1000u) << name;
    EXPECT_TRUE(a == b) << name;
  }
  worker_threads_setting() = 0;
}

}  // namespace
}  // namespace lt
