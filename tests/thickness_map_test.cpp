// Thickness maps and lobe ramps as scene inputs (load/thickness_map.h): what a file becomes
// (linear data, channel selection, orientation, float EXR), and every bad map as one error line
// naming the scene, the key and the map, exit 2, nothing written.
#include "load/thickness_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"
#include "load/load_scene.h"
#include "map_test_util.h"
#include "model/texture_sampling.h"
#include "render/session.h"
#include "scene/scene.h"
#include "scene/scene_parse.h"

namespace lt {
namespace {

using json = nlohmann::json;

class ThicknessMapFile : public ::testing::Test {
 protected:
  void SetUp() override { test::write_uv_quad(dir_.path()); }
  std::shared_ptr<const TextureMap> load(const std::string& name, const std::string& channels) {
    return load_thickness_map(dir_ / name, channels, "s.json", "key");
  }
  std::string error_of(const std::string& scene_text) {
    try {
      load_scene(parse_scene(scene_text, dir_ / "s.json", dir_.path()));
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  test::TempDir dir_;
};

TEST_F(ThicknessMapFile, EightBitTexelsAreLinearDataEvenWhenTheFileSaysSrgb) {
  // 2x2 grey, top row first: 0, 64 / 128, 255, declared sRGB (libpng writes an sRGB chunk).
  test::write_test_image(dir_ / "m.png", 2, 2, 1, {0, 64 / 255.f, 128 / 255.f, 1}, "sRGB");
  const auto m = load("m.png", "rgb");
  EXPECT_TRUE(m->grey);
  EXPECT_TRUE(m->exact_in_8_bits());
  EXPECT_EQ(m->source_bits, 8);
  // v / 255 exactly (sRGB decoding would make 64 into 0.0513); the image's top row is row 1
  // (v = 1 at the top).
  EXPECT_FLOAT_EQ(m->texture.texel(0, 1).x, 0.0f);
  EXPECT_FLOAT_EQ(m->texture.texel(1, 1).x, 64 / 255.f);
  EXPECT_FLOAT_EQ(m->texture.texel(0, 0).x, 128 / 255.f);
  EXPECT_FLOAT_EQ(m->texture.texel(1, 0).z, 1.0f);
  // The sampler's v = 0 is the image's bottom row.
  EXPECT_NEAR(model::sample_bilinear(m->texture, {0.25, 0.0}).x, 128 / 255.0, 1e-7);
  EXPECT_NEAR(model::sample_bilinear(m->texture, {0.25, 1.0}).x, 0.0, 1e-7);
}

TEST_F(ThicknessMapFile, EachChannelSelectionTakesItsChannel) {
  // One RGBA texel: r 0.2, g 0.4, b 0.6, a 0.8 (multiples of 1/255 nearest).
  const std::vector<float> rgba = {51 / 255.f, 102 / 255.f, 153 / 255.f, 204 / 255.f};
  test::write_test_image(dir_ / "c.png", 1, 1, 4, rgba);
  const auto all = load("c.png", "rgb");
  EXPECT_FALSE(all->grey);
  EXPECT_FLOAT_EQ(all->texture.texel(0, 0).x, rgba[0]);
  EXPECT_FLOAT_EQ(all->texture.texel(0, 0).y, rgba[1]);
  EXPECT_FLOAT_EQ(all->texture.texel(0, 0).z, rgba[2]);
  const char* names[] = {"r", "g", "b", "a"};
  for (int c = 0; c < 4; ++c) {
    const auto one = load("c.png", names[c]);
    EXPECT_TRUE(one->grey) << names[c];
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(one->texture.texel(0, 0)[k], rgba[c]) << names[c];
  }
}

TEST_F(ThicknessMapFile, ExrIsFloatAndKeepsValuesAboveOne) {
  test::write_test_image(dir_ / "f.exr", 2, 1, 3, {1.5f, 0.25f, 0.125f, 0, 2, 3});
  const auto m = load("f.exr", "rgb");
  EXPECT_TRUE(m->source_float);
  EXPECT_FALSE(m->exact_in_8_bits());
  EXPECT_EQ(m->texture.texel(0, 0), glm::dvec3(1.5, 0.25, 0.125));
  EXPECT_EQ(m->texture.texel(1, 0), glm::dvec3(0, 2, 3));
}

TEST_F(ThicknessMapFile, BadMapsNameTheSceneTheKeyAndTheMap) {
  const std::string key = "materials.skin.translucency.thickness.texture";
  auto expect_error = [&](const std::string& map, const std::string& channels,
                          const std::string& what, const std::string& where) {
    const std::string e = error_of(
        test::map_scene(R"({"texture": ")" + map + R"(", "channels": ")" + channels + R"("})"));
    EXPECT_NE(e.find("s.json:" + where), std::string::npos) << e;
    EXPECT_NE(e.find(what), std::string::npos) << e;
    if (where == key) EXPECT_NE(e.find(map), std::string::npos) << e;
  };
  expect_error("missing.png", "r", "thickness map file not found", key);
  test::write_file(dir_ / "garbage.png", "this is not a PNG");
  expect_error("garbage.png", "r", "cannot read image", key);
  // A PNG whose header says 0 x 0.
  std::string zero = "\x89PNG\r\n\x1a\n";
  zero += std::string("\0\0\0\x0dIHDR\0\0\0\0\0\0\0\0\x08\0\0\0\0\0\0\0\0", 25);
  test::write_file(dir_ / "zero.png", zero);
  expect_error("zero.png", "r", "zero.png", key);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  test::write_test_image(dir_ / "nan.exr", 3, 2, 1, {0, 0, 0, 0, nan, 0});
  expect_error("nan.exr", "r", "texel x 1, y 1 (from the top left) is NaN", key);
  test::write_test_image(dir_ / "inf.exr", 2, 1, 3, {0, 0, 0, 0, 0, inf});
  expect_error("inf.exr", "rgb", "texel x 1, y 0 (from the top left) is infinite", key);
  test::write_test_image(dir_ / "neg.exr", 1, 1, 1, {-0.5f});
  expect_error("neg.exr", "r", "is -0.5, out of range", key);
  test::write_test_image(dir_ / "grey.png", 1, 1, 1, {0.5f});
  expect_error("grey.png", "g", "has no g channel (it has one grey channel", key);
  test::write_test_image(dir_ / "rgb.png", 1, 1, 3, {0.5f, 0.5f, 0.5f});
  expect_error("rgb.png", "a", "has no a channel (it has r, g, b)", key);
  expect_error("rgb.png", "rg", "must be \"rgb\", \"r\", \"g\", \"b\" or \"a\", not \"rg\"",
               "materials.skin.translucency.thickness.channels");
  EXPECT_NE(error_of(test::map_scene(R"({"texture": "rgb.png", "scale": 2})"))
                .find("s.json:materials.skin.translucency.thickness.scale: unknown key"),
            std::string::npos);
}

TEST_F(ThicknessMapFile, AMapMaterialOnAMeshWithoutUvsNamesBoth) {
  test::write_test_image(dir_ / "rgb.png", 1, 1, 3, {0.5f, 0.5f, 0.5f});
  test::write_uv_quad(dir_.path(), false);
  const std::string e =
      error_of(test::map_scene(R"({"texture": "rgb.png"})", "quad_without_uvs.gltf"));
  EXPECT_NE(e.find("quad_without_uvs.gltf:/meshes/0/primitives/0"), std::string::npos) << e;
  EXPECT_NE(e.find("material \"skin\" samples the thickness map"), std::string::npos) << e;
  EXPECT_NE(e.find("has no texture coordinates (UVs)"), std::string::npos) << e;
  // A mesh file (OBJ without vt) the same way, under the scene's own key.
  test::write_file(dir_ / "quad.obj", test::quad_obj());
  std::string scene = test::map_scene(R"({"texture": "rgb.png"})");
  scene.replace(scene.find(R"("gltf": "uv_quad.gltf")"), 22, R"("mesh": "quad.obj")");
  const std::string o = error_of(scene);
  EXPECT_NE(o.find("s.json:objects[0].mesh: material \"skin\" samples the thickness map"),
            std::string::npos)
      << o;
  EXPECT_NE(o.find("quad.obj has no texture coordinates"), std::string::npos) << o;
}

TEST_F(ThicknessMapFile, RampIsOneRowHigh) {
  test::write_test_image(dir_ / "ramp.png", 4, 1, 3, std::vector<float>(12, 0.5f));
  test::write_test_image(dir_ / "tall.png", 4, 2, 1, std::vector<float>(8, 0.5f));
  test::write_test_image(dir_ / "rgb.png", 1, 1, 3, {0.5f, 0.5f, 0.5f});
  const Scene s = load_scene(
      parse_scene(test::map_scene(R"({"texture": "rgb.png"})", "uv_quad.gltf", "ramp.png"),
                  dir_ / "s.json", dir_.path()));
  const Translucency& tr = *s.materials.at(0).translucency;
  ASSERT_TRUE(tr.ramp);
  EXPECT_EQ(tr.ramp->texture.width, 4);
  EXPECT_TRUE(scene_needs(s).any_ramp);
  EXPECT_TRUE(scene_needs(s).any_thickness_map);
  const std::string e =
      error_of(test::map_scene(R"({"texture": "rgb.png"})", "uv_quad.gltf", "tall.png"));
  EXPECT_NE(e.find("s.json:materials.skin.translucency.ramp: lobe ramp file"), std::string::npos)
      << e;
  EXPECT_NE(e.find("tall.png is 4x2: a ramp is one row high"), std::string::npos) << e;
}

// Through the binary: exit 2, one line naming scene, key and map, and no output file.
TEST_F(ThicknessMapFile, RenderOfABadMapExitsTwoAndWritesNothing) {
  test::write_file(dir_ / "s.json", test::map_scene(R"({"texture": "missing.exr"})"));
  for (const char* path : {"reference", "glsl", "arbfp", "combiners", "half"}) {
    const fs::path out = dir_ / "out.png";
    const test::RunResult r = test::run_ltrender("render " + (dir_ / "s.json").string() +
                                                 " --path " + path + " -o " + out.string());
    EXPECT_EQ(r.exit_code, 2) << path;
    EXPECT_NE(r.err.find("s.json:materials.skin.translucency.thickness.texture: thickness map "
                         "file not found: "),
              std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("missing.exr"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out)) << path;
  }
}

// A glTF object's override (gltf_material_override_test.cpp) giving a mapped thickness: the same
// image, on reference and gx, as the map's own test scene, whose one scene material reads the map
// for the whole object.
TEST(GltfMaterialOverrideMap, AThicknessMapGivenByTheOverrideIsSampledAsAScenesOwn) {
  test::TempDir dir;
  test::write_uv_quad(dir.path());
  std::vector<float> grey;
  for (int i = 0; i < 16; ++i) grey.push_back(static_cast<float>(i) / 15);
  test::write_test_image(dir / "map.png", 4, 4, 1, grey);
  const std::string thickness = R"({"texture": "map.png"})";
  const json own = json::parse(test::map_scene(thickness));
  json over = own;
  over["materials"] = json::object();
  over["objects"][0].erase("material");
  over["objects"][0]["materials"] = {{"*", own["materials"]["skin"]}};
  const Scene a = load_scene(parse_scene(own.dump(), dir / "own.json", dir.path()));
  const Scene b = load_scene(parse_scene(over.dump(), dir / "over.json", dir.path()));
  ASSERT_EQ(b.materials.at(0).translucency->thickness_source, ThicknessSource::Texture);
  for (const char* path : {"reference", "gx"}) {
    const Image want = render_scene(a, path, "", 64, 64);
    EXPECT_NE(want.at(8, 8)[0], want.at(56, 56)[0]) << path << ": the map varies";
    EXPECT_EQ(render_scene(b, path, "", 64, 64).rgba, want.rgba) << path;
  }
}

}  // namespace
}  // namespace lt
