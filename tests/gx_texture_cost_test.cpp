// paths/gx/gx_budget frame_texture_cost: the textures a scene's frame loads as MEM1 holds them.
// The expectations are the tile arithmetic of each format written out here (I8: 8x4-texel tiles
// of 32 bytes; RGB565: 4x4 of 32; RGBA8: 4x4 of 64 [DHW TextureDecoder_Common.cpp block sizes]),
// from the scene's own map sizes, not from the function under test's helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
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

// CI4: 8x8-texel tiles of 32 bytes; the palette one IA8 entry (2 bytes) a distinct intensity up
// to 16 (gx/palette.h: one box a colour when there are no more colours than entries), from a
// 32-byte boundary. TMEM: one draw loads the LUT and the map, each under its 64 KiB region, and
// the palette's whole GX_TLUT0 region, 256 entries of 2 bytes.
TEST(GxTextureCost, AColourIndexedMapIsItsTilesAndItsPaletteAndItsTlutRegionInTmem) {
  const Scene scene = load_scene(test::source_dir() / "scenes/maps/sphere_map.json");
  const auto& map = scene.materials[0].translucency->thickness_map;
  ASSERT_TRUE(map && map->grey);
  const int w = map->texture.width, h = map->texture.height;
  std::set<long> intensities;
  for (size_t i = 0; i < map->texture.texels.size(); i += 3)
    intensities.insert(std::lround(map->texture.texels[i] * 255.0));
  const std::size_t entries = std::min<std::size_t>(16, intensities.size());
  const std::size_t lut = tiles(256, 8) * 32, ci4 = tiles(w, 8) * tiles(h, 8) * 32;
  const FrameTextureCost c = cost_of(scene, "t=vertex:map=ci4");
  EXPECT_EQ(c.textures, 2u);
  EXPECT_EQ(c.texture_bytes, lut + ci4);
  EXPECT_EQ(c.tlut_bytes, (entries * 2 + 31) / 32 * 32);
  EXPECT_EQ(c.tmem_bytes, lut + ci4 + 256 * 2);
  EXPECT_TRUE(c.fits_tmem());
  // As I8, no palette: the LUT and the map's 8x4 tiles.
  const FrameTextureCost i8 = cost_of(scene, "t=vertex");
  EXPECT_EQ(i8.tmem_bytes, lut + tiles(w, 8) * tiles(h, 4) * 32);
  EXPECT_EQ(i8.textures_over_cache, 0u);
  EXPECT_EQ(i8.overlapping_regions, 0u);
}

// The 211x211 albedo map wraps, so the gx path stores it at 256x256 (pass_planner_albedo.cpp: a
// repeating side at the next power of two). As RGBA8 (4x4 tiles of 64 bytes) that is 256 KiB,
// over its region's two 32 KiB caches: it occupies the 64 KiB and is streamed through them; as
// CMPR (8x8 tiles of 32 bytes) it is 32 KiB and stays resident.
TEST(GxTextureCost, AMapOverItsCacheRegionIsCountedAndOccupiesTheRegion) {
  const Scene scene = load_scene(test::source_dir() / "scenes/debian_box_textured.json");
  ASSERT_EQ(scene.materials.size(), 1u);
  const auto& albedo = scene.materials[0].albedo_map;
  ASSERT_TRUE(albedo);
  ASSERT_EQ(albedo->texture.width, 211);
  ASSERT_EQ(albedo->texture.height, 211);
  ASSERT_NE(albedo->texture.wrap_s, TextureWrap::ClampToEdge);
  ASSERT_NE(albedo->texture.wrap_t, TextureWrap::ClampToEdge);
  const int w = 256, h = 256;
  const std::size_t lut = tiles(256, 8) * 32;
  const FrameTextureCost rgba8 = cost_of(scene, "t=vertex");
  EXPECT_EQ(rgba8.textures_over_cache, 1u);
  EXPECT_FALSE(rgba8.fits_tmem());
  EXPECT_EQ(rgba8.tmem_bytes, lut + 65536);
  const FrameTextureCost cmpr = cost_of(scene, "t=vertex:map=cmpr");
  EXPECT_EQ(cmpr.textures_over_cache, 0u);
  EXPECT_TRUE(cmpr.fits_tmem());
  EXPECT_EQ(cmpr.tmem_bytes, lut + tiles(w, 8) * tiles(h, 8) * 32);
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
  EXPECT_EQ(detail("tmem_bytes"), static_cast<int>(c.tmem_bytes));
  EXPECT_EQ(detail("tmem_textures_over_cache"), 0);
  EXPECT_EQ(detail("tmem_overlapping_regions"), 0);
  bool fits = false;
  for (const auto& d : r.details) fits |= d.key == "tmem_fits" && d.text == "yes";
  EXPECT_TRUE(fits);
}

}  // namespace
}  // namespace lt::gx
