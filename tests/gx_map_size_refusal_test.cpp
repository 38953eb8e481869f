// A scene's map the console cannot take as the variant asks (issue 47 "Bad input"): a map whose
// side is not a power of two under :wrap=repeat or :mip= (the console masks and halves the
// sizes), and a map over 1024 texels a side (the largest GX texture), are refused in one line
// naming the scene and the material's map key; `ltrender render` exits 2 and writes nothing.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.h"
#include "image/png_file.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

// sphere_map.json's sphere with a grey thickness map of `width` x `height` texels.
fs::path scene_with_map(const test::TempDir& dir, int width, int height) {
  std::vector<uint8_t> rgb(static_cast<size_t>(width) * height * 3);
  for (size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<uint8_t>(i / 3 % 251);
  std::string error;
  const fs::path png = dir / ("map_" + std::to_string(width) + ".png");
  EXPECT_TRUE(write_png_rgb8(png.string(), width, height, rgb.data(), error)) << error;
  const fs::path scene = dir / ("scene_" + std::to_string(width) + ".json");
  test::write_file(
      scene,
      R"({ "image": { "width": 64, "height": 48 }, "camera": { "eye": [0, 0, 4], "target": [0, 0, 0] },
  "materials": { "marble": { "albedo": [0.9, 0.88, 0.85], "translucency": { "power": 8,
    "distortion": 0.2, "ambient": 0.05, "thickness": { "texture": ")" +
          png.filename().string() + R"(", "channels": "r" } } } },
  "lights": [ { "type": "directional", "direction": [0.25, 0.1, 1], "translucency_scale": 2 } ],
  "objects": [ { "gltf": ")" +
          (test::source_dir() / "scenes/maps/uv_sphere.glb").string() +
          R"(", "material": "marble" } ] })");
  return scene;
}

TEST(GxMapSizeRefusal, RepeatAndMipmapsNeedPowersOfTwoAndNoMapIsOver1024) {
  test::TempDir dir;
  const fs::path npot = scene_with_map(dir, 24, 8);
  const Scene scene = load_scene(npot);
  EXPECT_NO_THROW(render_scene(scene, "gx", "t=vertex", 16, 16)) << "24x8 clamped draws";
  for (const char* variant : {"t=vertex:wrap=repeat", "t=vertex:mip=lin"}) {
    SCOPED_TRACE(variant);
    try {
      (void)render_scene(scene, "gx", variant, 16, 16);
      FAIL() << "a 24x8 map was drawn";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), npot.string());
      EXPECT_EQ(e.where(), "materials.marble.translucency.thickness");
      EXPECT_NE(e.what_only().find("is 24x8 texels"), std::string::npos) << e.what();
      EXPECT_NE(e.what_only().find("needs sides that are powers of two"), std::string::npos)
          << e.what();
    }
  }
  // Over 1024 a side, through the command: exit 2, one line, no image.
  const fs::path wide = scene_with_map(dir, 1040, 1);
  const fs::path out = dir / "out.png";
  const test::RunResult r =
      test::run_ltrender("render " + wide.string() + " --path gx -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(wide.string() + ":materials.marble.translucency.thickness"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("is 1040x1 texels; a GX texture is at most 1024 a side"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace lt
