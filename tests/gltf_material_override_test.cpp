// Translucency for assets that do not carry it: a JSON scene's glTF object gives the file's
// materials (by name, "#N" or "*") a scene material's keys, without editing the file. (A mapped
// thickness given so: thickness_map_test.cpp, where the map images are written.)
#include <gtest/gtest.h>

#include "core/error.h"
#include "gltf_test_util.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "scene/scene.h"
#include "scene/scene_parse.h"

namespace lt {
namespace {

using json = nlohmann::json;

class GltfMaterialOverride : public ::testing::Test {
 protected:
  // A plain asset: the unit quad with two diffuse materials, "paint" (albedo 0.8 0.6 0.4) on the
  // first primitive and "#1" (unnamed, albedo 0.5) on the second (the same quad again, behind),
  // and a third primitive without a material (glTF's default).
  void SetUp() override {
    test::GltfWriter w;
    const int pos = w.floats({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0}, "VEC3", 3);
    const int idx = w.accessor(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}, 5123, "SCALAR", 1);
    w.doc["materials"] = {
        {{"name", "paint"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.6, 0.4, 1}}}}},
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}}}}};
    const json prim = {{"attributes", {{"POSITION", pos}}}, {"indices", idx}};
    json p0 = prim, p1 = prim;
    p0["material"] = 0;
    p1["material"] = 1;
    w.doc["meshes"].push_back({{"name", "quad"}, {"primitives", {p0, p1, prim}}});
    w.root({{"name", "Quad"}, {"mesh", 0}});
    w.write_gltf(dir_.path(), "plain");
    // "single": the first primitive alone, for images without coplanar twins.
    w.doc["meshes"][0]["primitives"] = {p0};
    w.write_gltf(dir_.path(), "single");
  }
  json scene_json(const json& object) const {
    return {{"image", {{"width", 64}, {"height", 48}}},
            {"camera", {{"eye", {0, 0, 3}}, {"target", {0, 0, 0}}}},
            {"materials", {{"unused", json::object()}}},
            {"lights", {{{"type", "directional"}, {"direction", {0, 0, 1}}}}},
            {"objects", {object}}};
  }
  Scene parse(const json& object) {
    return load_scene(parse_scene(scene_json(object).dump(), dir_ / "s.json", dir_.path()));
  }
  const Material& material_of(const Scene& s, std::size_t object) {
    return s.materials.at(static_cast<std::size_t>(s.objects.at(object).material));
  }
  test::TempDir dir_;
};

const json kJade = {
    {"translucency", {{"power", 3}, {"distortion", 0.25}, {"ambient", 0.1}, {"thickness", 0.5}}}};

TEST_F(GltfMaterialOverride, ByNameTheTranslucencyIsAddedAndTheFilesAlbedoKept) {
  const Scene s = parse({{"gltf", "plain.gltf"}, {"materials", {{"paint", kJade}}}});
  const Material& paint = material_of(s, 0);
  EXPECT_EQ(paint.name, "paint");
  EXPECT_EQ(paint.albedo, glm::dvec3(0.8, 0.6, 0.4));
  ASSERT_TRUE(paint.translucency);
  EXPECT_EQ(paint.translucency->power, 3);
  EXPECT_EQ(paint.translucency->distortion, 0.25);
  EXPECT_EQ(paint.translucency->ambient, 0.1);
  EXPECT_EQ(paint.translucency->thickness, glm::dvec3(0.5));
  EXPECT_FALSE(material_of(s, 1).translucency) << "#1 is not selected";
  EXPECT_FALSE(material_of(s, 2).translucency) << "the default material is not selected";
}

TEST_F(GltfMaterialOverride, ANameWinsOverTheIndexAndTheStarTakesTheRest) {
  json jade2 = kJade;
  jade2["albedo"] = {0.1, 0.2, 0.3};
  jade2["translucency"]["power"] = 7;
  const Scene s = parse(
      {{"gltf", "plain.gltf"}, {"materials", {{"#0", jade2}, {"paint", kJade}, {"*", jade2}}}});
  EXPECT_EQ(material_of(s, 0).translucency->power, 3) << "the name, not #0";
  EXPECT_EQ(material_of(s, 0).albedo, glm::dvec3(0.8, 0.6, 0.4));
  EXPECT_EQ(material_of(s, 1).translucency->power, 7) << "*";
  EXPECT_EQ(material_of(s, 1).albedo, glm::dvec3(0.1, 0.2, 0.3));
  EXPECT_EQ(material_of(s, 2).translucency->power, 7) << "* takes the default material too";
}

TEST_F(GltfMaterialOverride, AnIndexSelectsAnUnnamedMaterial) {
  const Scene s = parse({{"gltf", "plain.gltf"}, {"materials", {{"#1", kJade}}}});
  EXPECT_FALSE(material_of(s, 0).translucency);
  ASSERT_TRUE(material_of(s, 1).translucency);
  EXPECT_EQ(material_of(s, 1).albedo, glm::dvec3(0.5));
}

// The same look by two routes: the override on the file's material, and a scene material with
// the file's albedo and the same keys given to the whole object.
TEST_F(GltfMaterialOverride, RendersAsTheSameSceneMaterialGivenWhole) {
  const Scene over = parse({{"gltf", "single.gltf"}, {"materials", {{"paint", kJade}}}});
  json whole = scene_json({{"gltf", "single.gltf"}, {"material", "jade"}});
  json jade = kJade;
  jade["albedo"] = {0.8, 0.6, 0.4};
  whole["materials"]["jade"] = jade;
  const Scene given = load_scene(parse_scene(whole.dump(), dir_ / "w.json", dir_.path()));
  const Image a = render_scene(over, "reference", "", 64, 48);
  const Image b = render_scene(given, "reference", "", 64, 48);
  ASSERT_GT(a.at(32, 24)[0], 0.0f) << "backlit: the lobe alone lights it";
  EXPECT_EQ(a.rgba, b.rgba);
}

TEST_F(GltfMaterialOverride, AnUnknownNameOrIndexIsOneLineNamingTheKey) {
  for (const char* selector : {"nope", "#2"}) {
    test::write_file(
        dir_ / "s.json",
        scene_json({{"gltf", "plain.gltf"}, {"materials", {{selector, kJade}}}}).dump());
    const auto r = test::run_ltrender("info " + (dir_ / "s.json").string());
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_EQ(
        r.err.rfind("ltrender: error: " + (dir_ / "s.json").string() + ":objects[0].materials." +
                        selector + ": no material named \"" + selector + "\"",
                    0),
        0u)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
}

TEST_F(GltfMaterialOverride, BadOverridesAreRefusedWithTheirKey) {
  auto error = [&](const json& object) -> std::string {
    try {
      parse(object);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(accepted)";
  };
  EXPECT_NE(error({{"gltf", "plain.gltf"}, {"material", "unused"}, {"materials", {{"*", kJade}}}})
                .find("objects[0].materials: an object has \"material\""),
            std::string::npos);
  json typo = kJade;
  typo["translucency"]["powr"] = 2;
  EXPECT_NE(error({{"gltf", "plain.gltf"}, {"materials", {{"paint", typo}}}})
                .find("objects[0].materials.paint.translucency.powr: unknown key"),
            std::string::npos);
  EXPECT_NE(error({{"gltf", "plain.gltf"}, {"materials", json::object()}})
                .find("objects[0].materials: expected a non-empty object"),
            std::string::npos);
  // "vertex" thickness on a primitive without COLOR_0: named like the file's own.
  json vertex = kJade;
  vertex["translucency"]["thickness"] = "vertex";
  EXPECT_NE(error({{"gltf", "plain.gltf"}, {"materials", {{"paint", vertex}}}})
                .find("takes its thickness from COLOR_0, which this primitive lacks"),
            std::string::npos);
}

}  // namespace
}  // namespace lt
