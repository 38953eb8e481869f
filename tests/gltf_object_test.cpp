// A glTF file as an object of a JSON scene: {"gltf": FILE, "node": NAME, "material": M}.
#include <gtest/gtest.h>

#include <set>

#include "core/error.h"
#include "gltf_test_util.h"
#include "load/load_scene.h"
#include "scene/scene.h"
#include "scene/scene_parse.h"

namespace lt {
namespace {

using json = nlohmann::json;

class GltfObject : public ::testing::Test {
 protected:
  // The volume quad's file, its Quad node under a parent translated by (0, 5, 0).
  void SetUp() override {
    test::GltfWriter w = test::volume_quad();
    w.doc["nodes"][0]["translation"] = {0, 0, 0};
    const int parent = w.node({{"name", "Parent"}, {"translation", {0, 5, 0}}, {"children", {0}}});
    w.doc["scenes"][0]["nodes"][0] = parent;
    w.write_gltf(dir_.path(), "m");
  }
  Scene parse(const json& object) {
    const json s = {{"image", {{"width", 64}, {"height", 48}}},
                    {"camera", {{"eye", {0, 0, 4}}, {"target", {0, 0, 0}}}},
                    {"materials", {{"white", {{"albedo", {1, 1, 1}}}}}},
                    {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}}}},
                    {"objects", {object}}};
    return load_scene(parse_scene(s.dump(), dir_ / "s.json", dir_.path()));
  }
  test::TempDir dir_;
};

TEST_F(GltfObject, ANodeIsPlacedByItsAncestorsThenTheObjectsTransform) {
  const Scene s = parse({{"gltf", "m.gltf"},
                         {"node", "Quad"},
                         {"material", "white"},
                         {"transform", {{"translate", {1, 0, 0}}}}});
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].mesh.positions[0], glm::dvec3(0, 4, 0));  // (-1,-1,0) + (0,5,0) + (1,0,0)
  EXPECT_EQ(s.objects[0].material, 0);
  EXPECT_EQ(s.materials.size(), 1u);
  EXPECT_EQ(s.lights.size(), 1u) << "the file's light is not imported";
}

TEST_F(GltfObject, WithoutAMaterialTheFilesMaterialsAreMappedAndAppended) {
  const Scene s = parse({{"gltf", "m.gltf"}});
  ASSERT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(s.materials.size(), 2u);
  EXPECT_EQ(s.materials[1].name, "jade");
  EXPECT_EQ(s.objects[0].material, 1);
  EXPECT_TRUE(s.materials[1].translucency.has_value());
  EXPECT_EQ(s.lights.size(), 1u) << "the file's light is not imported";
  bool noted = false;
  for (const auto& n : s.import_notes) noted |= n.find("brings no lights") != std::string::npos;
  EXPECT_TRUE(noted);
}

// Two objects of one file share its materials and its notes (issue 24: `info` listed each
// twice, and gx refused the scene for two materials with one C name).
TEST_F(GltfObject, TwoObjectsOfOneFileShareItsMaterialsAndNotes) {
  const json s = {
      {"image", {{"width", 32}, {"height", 24}}},
      {"camera", {{"eye", {0, 0, 4}}, {"target", {0, 0, 0}}}},
      {"materials", {{"white", {{"albedo", {1, 1, 1}}}}}},
      {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}}}},
      {"objects",
       {{{"gltf", "m.gltf"}}, {{"gltf", "./m.gltf"}, {"transform", {{"translate", {3, 0, 0}}}}}}}};
  test::write_file(dir_ / "two.json", s.dump());
  const Scene scene = load_scene(dir_ / "two.json");
  ASSERT_EQ(scene.objects.size(), 2u);
  ASSERT_EQ(scene.materials.size(), 2u) << "white, and jade once";
  EXPECT_EQ(scene.objects[0].material, 1);
  EXPECT_EQ(scene.objects[1].material, 1);
  EXPECT_NE(scene.objects[0].mesh.positions[0], scene.objects[1].mesh.positions[0]);
  std::set<std::string> unique(scene.import_notes.begin(), scene.import_notes.end());
  EXPECT_EQ(unique.size(), scene.import_notes.size());
  EXPECT_FALSE(scene.import_notes.empty());

  const auto info = test::run_ltrender("info " + (dir_ / "two.json").string());
  EXPECT_EQ(info.exit_code, 0) << info.err;
  size_t jade_lines = 0;
  for (size_t at = info.out.find("  material jade:"); at != std::string::npos;
       at = info.out.find("  material jade:", at + 1))
    ++jade_lines;
  EXPECT_EQ(jade_lines, 1u) << info.out;
  EXPECT_NE(info.out.find("path gx"), std::string::npos) << info.out;
}

TEST_F(GltfObject, AnUnknownNodeOrAMissingFileNamesTheScenesKey) {
  try {
    parse({{"gltf", "m.gltf"}, {"node", "Head"}});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "objects[0].node");
  }
  try {
    parse({{"gltf", "nope.glb"}});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "objects[0].gltf");
  }
  EXPECT_THROW(parse({{"gltf", "m.gltf"}, {"mesh", "m.gltf"}}), InputError);
}

}  // namespace
}  // namespace lt
