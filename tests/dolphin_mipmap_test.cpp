// Mipmapped maps (`:mip=`, `:mip-bias=`, `:wrap=`, gx_variant.h) judged by Dolphin: the map
// scenes' colour map (scenes/maps/sphere_rgb_ramp.json) as CMPR, RGB565 and CI8 and their grey
// map (scenes/maps/sphere_map.json) as I8 and CI4, each with its full mip chain in the log's
// memory after level 0, GX_LIN_MIP_LIN or GX_NEAR_MIP_NEAR, LOD biases of both signs, clamped
// and repeated, the spheres drawn small (a wide field of view) so the maps are minified, not
// only biased down; then negative biases on spheres drawn small (110-130 degrees) and diagonal
// LOD (:mip-lod=diagonal, GX_InitTexObjLOD's edgelod GX_FALSE) with biases of both signs. The
// frames play in one FIFO log (one Dolphin start). Dolphin's software
// renderer computes each 2x2 block's LOD and samples the levels [DSW Rasterizer.cpp
// CalculateLOD] [DSW TextureSampler.cpp Sample, SampleMip]; its picture must be ltrender's
// `:out=xfb` one, pixel for pixel.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <utility>

#include "dolphin_util.h"
#include "load/load_scene.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

struct MipFrame {
  const char* scene;
  const char* variant;
  double fov_y_deg;  // the scenes' own 40, or wider: a smaller sphere, a minified map
};

TEST(DolphinMipmap, MipmappedMapsAreDolphinsPicture) {
  // The LOD comes from texture coordinates in texels of level 0 (gx_state.h TexCoordScale), and
  // these maps are small (32x16, 64x32 texels) for spheres of this size: they reach level 1 and
  // beyond only with a bias of a few levels, or at their rim.
  const MipFrame cases[] = {
      {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=cmpr:mip=lin:mip-bias=1.5", 40},
      {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=rgb565:mip=lin:mip-bias=3.5:wrap=repeat",
       40},
      {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=ci8:mip=near:mip-bias=3", 40},
      {"scenes/maps/sphere_map.json", "t=vertex:mip=near:mip-bias=3.75:wrap=repeat", 40},
      {"scenes/maps/sphere_map.json", "t=vertex:map=ci4:mip=lin:mip-bias=2.5", 40},
      {"scenes/maps/sphere_map.json", "t=vertex:mip=lin:mip-bias=3", 110},
      // Negative biases: only a small sphere's rim reaches past level 0.
      {"scenes/maps/sphere_map.json", "t=vertex:mip=lin:mip-bias=-0.5", 120},
      {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=rgb565:mip=near:mip-bias=-1", 130},
      // Diagonal LOD: the steps across and down summed, not their larger (texture_lod.h).
      {"scenes/maps/sphere_rgb_ramp.json",
       "t=vertex:map=rgb565:mip=lin:mip-bias=3:mip-lod=diagonal", 40},
      {"scenes/maps/sphere_map.json", "t=vertex:map=ci4:mip=near:mip-bias=2:mip-lod=diagonal", 110},
      {"scenes/maps/sphere_rgb_ramp.json",
       "t=vertex:map=cmpr:mip=lin:mip-bias=-0.5:mip-lod=diagonal", 125}};
  constexpr size_t kFrames = std::size(cases);
  std::vector<Scene> scenes;
  for (const MipFrame& c : cases) {
    scenes.push_back(load_scene(test::source_dir() / c.scene));
    scenes.back().width = test::kDolphinWidth;
    scenes.back().height = test::kDolphinHeight;
    scenes.back().camera.fov_y_deg = c.fov_y_deg;
  }
  std::vector<std::string> variants;
  for (const MipFrame& c : cases) variants.push_back(c.variant);
  const std::vector<Image> dolphin = test::dolphin_pictures_of(scenes, variants);
  ASSERT_EQ(dolphin.size(), kFrames);
  for (size_t k = 0; k < kFrames; ++k) {
    const std::string variant = std::string(cases[k].variant) + ":out=xfb";
    const Image ours =
        render_scene(scenes[k], "gx", variant, test::kDolphinWidth, test::kDolphinHeight);
    // The mip chain must change the picture, or the frame judges nothing the tree had before.
    std::string plain = cases[k].variant;
    plain = plain.substr(0, plain.find(":mip=")) + ":out=xfb";
    const Image without =
        render_scene(scenes[k], "gx", plain, test::kDolphinWidth, test::kDolphinHeight);
    EXPECT_GT(test::picture_difference(ours, without).differ, 0u)
        << cases[k].variant << " draws what " << plain << " draws";
    // Diagonal LOD must change the picture too, or Dolphin judged edge LOD again.
    std::string edge = cases[k].variant;
    if (const size_t at = edge.find(":mip-lod=diagonal"); at != std::string::npos) {
      edge.erase(at, std::string(":mip-lod=diagonal").size());
      const Image edge_lod = render_scene(scenes[k], "gx", edge + ":out=xfb", test::kDolphinWidth,
                                          test::kDolphinHeight);
      EXPECT_GT(test::picture_difference(ours, edge_lod).differ, 0u)
          << cases[k].variant << " draws what " << edge << " draws";
    }
    const test::PictureDifference d = test::picture_difference(ours, dolphin[k]);
    std::printf("| %s | %s | fov %g | %zu | %zu | %d |\n", cases[k].scene, cases[k].variant,
                cases[k].fov_y_deg, test::covered_pixels(ours), d.differ, d.max);
    EXPECT_GT(test::covered_pixels(ours), static_cast<size_t>(ours.pixel_count() / 400))
        << cases[k].variant << ": the scene covers almost nothing";
    EXPECT_EQ(d.differ, 0u) << cases[k].scene << " " << cases[k].variant << ": first at "
                            << d.first_x << "," << d.first_y << ", max " << d.max << " LSB";
  }
}

}  // namespace
}  // namespace lt
