// paths/gx/gx_budget frame_texture_cost: the textures a scene's frame loads as MEM1 holds them.
// The expectations are the tile arithmetic of each format written out here (I8: 8x4-texel tiles
// of 32 bytes; RGB565: 4x4 of 32; RGBA8: 4x4 of 64 [DHW TextureDecoder_Common.cpp block sizes]),
// from the scene's own map sizes, not from the function under test's helpers.
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "load/load_scene.h"
#include "paths/gx/gx_budget.h"
#include "paths/gx/gx_path.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::gx {
namespace {

std::size_t tiles(int texels, int tile) {
  return static_cast<std::size_t>((texels + tile - 1) / tile);
}

FrameTextureCost cost_of(const Scene& scene, const std::string& variant) {
  return frame_texture_cost(scene, scene_programs_for(scene, parse_gx_variant(variant), ""));
}

TEST(GxTextureCost, AGreyMapAndTheLutEachOnceWhateverThePassesThatLoadThem) {
  const Scene scene = load_scene(test::source_dir() / "scenes/maps/sphere_map.json");
  ASSERT_EQ(scene.materials.size(), 1u);
  ASSERT_EQ(scene.lights.size(), 2u);  // two passes, each loading the LUT and the map
  const auto& map = scene.materials[0].translucency->thickness_map;
  ASSERT_TRUE(map && map->grey);
  const int w = map->texture.width, h = map->texture.height;
  const FrameTextureCost c = cost_of(scene, "t=vertex");
  EXPECT_EQ(c.textures, 2u);
  // The map as GX_TF_I8, the 256-texel LUT as GX_TF_I8 (one row: one tile row of 4).
  EXPECT_EQ(c.texture_bytes, tiles(w, 8) * tiles(h, 4) * 32 + tiles(256, 8) * tiles(1, 4) * 32);
  EXPECT_EQ(c.tlut_bytes, 0u);
  // A smaller LUT is fewer bytes: 64 texels are 8 tiles.
  EXPECT_EQ(cost_of(scene, "t=vertex:lut=64").texture_bytes,
            tiles(w, 8) * tiles(h, 4) * 32 + tiles(64, 8) * 32);
}

TEST(GxTextureCost, AColourMapIsHalfTheBytesAsRgb565) {
  const Scene scene = load_scene(test::source_dir() / "scenes/maps/sphere_rgb_ramp.json");
  const std::string why = "a colour thickness map, loaded as RGBA8 by default";
  const auto& map = scene.materials.at(0).translucency->thickness_map;
  ASSERT_TRUE(map && !map->grey) << why;
  const int w = map->texture.width, h = map->texture.height;
  const FrameTextureCost rgba8 = cost_of(scene, "t=vertex");
  const FrameTextureCost rgb565 = cost_of(scene, "t=vertex:map=rgb565");
  EXPECT_EQ(rgba8.textures, rgb565.textures);
  EXPECT_EQ(rgba8.texture_bytes - rgb565.texture_bytes, tiles(w, 4) * tiles(h, 4) * (64 - 32))
      << why;
}

TEST(GxTextureCost, TheBudgetOfASceneCarriesTheFigures) {
  const Scene scene = load_scene(test::source_dir() / "scenes/maps/sphere_map.json");
  const budget::Report r = gx_budget_scene(scene, "", "wii-tev");
  const FrameTextureCost c = cost_of(scene, "t=vertex");
  auto detail = [&](const std::string& key) -> std::optional<int> {
    for (const auto& d : r.details)
      if (d.key == key) return d.number;
    return std::nullopt;
  };
  EXPECT_EQ(detail("textures"), static_cast<int>(c.textures));
  EXPECT_EQ(detail("texture_bytes"), static_cast<int>(c.texture_bytes));
  EXPECT_EQ(detail("tlut_bytes"), 0);
}

}  // namespace
}  // namespace lt::gx
