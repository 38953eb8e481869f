// The default light rig (docs/spec/scene-format.md, "Default lights"): a scene with no light and
// no ambient light is lit by a back light behind the object as the camera sees it and a front
// fill, with one warning line and a line in `info`; `--lights none` renders it unlit, silently.
#include "scene/default_lights.h"

#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "scene/scene.h"

namespace lt {
namespace {

// The volume quad of gltf_test_util.h without its KHR_lights_punctual light (node 1) and
// without ambient translucency, so each light's share is the lobe alone.
test::GltfWriter unlit_quad() {
  test::QuadParams q;
  q.transmission = 0;
  test::GltfWriter w = test::volume_quad(q);
  w.doc.erase("extensions");
  w.doc["nodes"][1].erase("extensions");
  auto& used = w.doc["extensionsUsed"];
  used.erase(std::find(used.begin(), used.end(), "KHR_lights_punctual"));
  return w;
}

TEST(DefaultLights, TheRigIsABackLightTowardsTheCameraAndAFillFromUpLeft) {
  test::TempDir dir;
  const Scene scene = load_scene(unlit_quad().write_gltf(dir.path(), "quad"));
  ASSERT_EQ(scene.lights.size(), 2u);
  EXPECT_FALSE(scene.default_lights.empty());
  // The camera sits on +Z looking down -Z with +Y up, so right is +X: the back light travels
  // +Z (towards the camera) and down by the rise, the fill -Z, down and right.
  const Light& back = scene.lights[0];
  const Light& fill = scene.lights[1];
  EXPECT_EQ(back.type, Light::Type::Directional);
  const glm::dvec3 back_dir = glm::normalize(glm::dvec3(0, -kBackLightRise, 1));
  const glm::dvec3 fill_dir = glm::normalize(glm::dvec3(0.5, -0.5, -1));
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(back.direction[c], back_dir[c], 1e-12) << c;
    EXPECT_NEAR(fill.direction[c], fill_dir[c], 1e-12) << c;
    EXPECT_EQ(back.color[c], 1.0);
    EXPECT_EQ(fill.color[c], kFillIntensity);
  }
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("no light and no ambient_light, lit by the default rig"),
            std::string::npos)
      << scene.warnings[0];
}

// V = N = +Z (orthographic). The back light's L = (0, rise, -1) / n, n = |(0, rise, 1)|: no
// diffuse (N.L < 0), lobe t = V.-(L + N d) = 1/n - d. The fill's L = (-0.5, 0.5, 1) / sqrt(1.5):
// diffuse kFill * N.L = kFill / sqrt(1.5), lobe 0 (V.-(L + N d) < 0). The volume quad's
// transmittance T = (sqrt 0.5, 0.5, 1), tint (1, 0.8, 0.6), albedo (0.9, 0.8, 0.7), power 2,
// distortion 0.5.
TEST(DefaultLights, TheBackLightShowsTheTranslucencyOfAFrontFacingQuad) {
  test::TempDir dir;
  const Scene scene = load_scene(unlit_quad().write_gltf(dir.path(), "quad"));
  const Image img = render_scene(scene, "reference", "", 64, 48);
  const double n = std::sqrt(1 + kBackLightRise * kBackLightRise);
  const double lobe = std::pow(1 / n - 0.5, 2);
  const double diffuse = kFillIntensity / std::sqrt(1.5);
  const double albedo[3] = {0.9, 0.8, 0.7}, t[3] = {std::sqrt(0.5), 0.5, 1},
               tint[3] = {1, 0.8, 0.6};
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(img.at(32, 24)[c], albedo[c] * (diffuse + lobe * t[c] * tint[c]), 1e-6) << c;
}

TEST(DefaultLights, ALightlessAssetRendersLitWithOneWarningAndInfoSaysSo) {
  test::TempDir dir;
  const fs::path file = unlit_quad().write_glb(dir.path(), "quad");
  const fs::path out = dir / "out.exr";
  const auto r = test::run_ltrender("render " + file.string() +
                                    " --path gx --width 64 --height 48 -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_EQ(r.err.rfind("ltrender: warning: " + file.string() + ": no light", 0), 0u) << r.err;
  const Image img = read_image(out);
  std::size_t covered = 0, lit = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      if (p[3] == 0) continue;
      ++covered;
      lit += p[0] > 0 && p[1] > 0 && p[2] > 0;
    }
  EXPECT_GT(covered, 64u * 48 / 4);
  EXPECT_EQ(lit, covered);
  const auto info = test::run_ltrender("info " + file.string());
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("lights: 2 from the default rig: a back light"), std::string::npos)
      << info.out;
}

TEST(DefaultLights, LightsNoneRendersUnlitAndSaysNothingMisleading) {
  test::TempDir dir;
  const fs::path file = unlit_quad().write_gltf(dir.path(), "quad");
  const fs::path out = dir / "out.exr";
  const auto r = test::run_ltrender("render " + file.string() +
                                    " --path reference --lights none --width 64 --height 48 -o " +
                                    out.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const Image img = read_image(out);
  EXPECT_EQ(img.at(32, 24)[3], 1.0f);  // covered
  for (int c = 0; c < 3; ++c) EXPECT_EQ(img.at(32, 24)[c], 0.0f) << c;
  const auto info = test::run_ltrender("info --lights none " + file.string());
  EXPECT_NE(info.out.find("lights: 0 from the scene"), std::string::npos) << info.out;
  EXPECT_EQ(info.out.find("default rig"), std::string::npos) << info.out;
  const auto bad = test::run_ltrender("info --lights off " + file.string());
  EXPECT_EQ(bad.exit_code, 2);
}

// Without a camera the importer frames the meshes, and `info` says so.
TEST(DefaultLights, AnAssetWithoutCameraOrLightIsFramedAndLit) {
  test::TempDir dir;
  test::GltfWriter w = unlit_quad();
  w.doc.erase("cameras");
  w.doc["nodes"][2].erase("camera");
  const fs::path file = w.write_gltf(dir.path(), "bare");
  const auto info = test::run_ltrender("info " + file.string());
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("default camera: no camera in the file, framing the meshes"),
            std::string::npos)
      << info.out;
  const Scene scene = load_scene(file);
  const Image img = render_scene(scene, "reference", "", 32, 32);
  EXPECT_EQ(img.at(16, 16)[3], 1.0f);
  EXPECT_GT(img.at(16, 16)[0], 0.0f);
}

// A scene that is lit by its ambient light alone keeps it: the rig is for scenes with nothing.
TEST(DefaultLights, AnAmbientLitJsonSceneGetsNoRig) {
  test::TempDir dir;
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "s.json", R"({"image": {"width": 8, "height": 8},
    "camera": {"eye": [0, 0, 3], "target": [0, 0, 0]}, "ambient_light": [0.1, 0.1, 0.1],
    "materials": {"m": {}}, "objects": [{"mesh": "quad.obj", "material": "m"}]})");
  const Scene scene = load_scene(dir / "s.json");
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_TRUE(scene.warnings.empty());
}

}  // namespace
}  // namespace lt
