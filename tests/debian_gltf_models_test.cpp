// Debian's glTF 2.0 test models (assimp-testmodels, /usr/share/assimp/models/glTF2/), every file:
// rendered lit through reference and gx, or refused for a stated reason. Each refusal is a file
// glTF 2.0 calls invalid, a required extension not decoded, or a file with no surface to draw.
// The table is docs/scenes-and-gltf.md's.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <set>

#include "core/error.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

const fs::path kModels = "/usr/share/assimp/models/glTF2";

enum class Outcome { Lit, Refused };

struct Model {
  std::string file;  // under kModels
  Outcome outcome;
  std::string reason;  // refused: a piece of the one-line error
  std::string why;     // refused: the category and what glTF 2.0 says (docs/scenes-and-gltf.md)
};

// The expectation of every file; a file the package adds or drops fails EveryFileIsInTheTable.
void PrintTo(const Model& m, std::ostream* os) {
  *os << m.file;
}

const std::vector<Model>& models() {
  static const std::vector<Model> table = {
      {"2CylinderEngine-glTF-Binary/2CylinderEngine.glb", Outcome::Lit, "", ""},
      {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", Outcome::Lit, "", ""},
      {"BoxTexcoords-glTF/boxTexcoords.gltf", Outcome::Lit, "", ""},
      {"BoxTextured-glTF-Binary/BoxTextured.glb", Outcome::Lit, "", ""},
      {"BoxTextured-glTF-Embedded/BoxTextured.gltf", Outcome::Lit, "", ""},
      {"BoxTextured-glTF-pbrSpecularGlossiness/BoxTextured.gltf", Outcome::Lit, "", ""},
      {"BoxTextured-glTF-techniqueWebGL/BoxTextured.gltf", Outcome::Refused,
       "/extensionsRequired/0: required extension KHR_technique_webgl is not supported",
       "required extension not decoded: KHR_technique_webgl (a glTF 1.0 technique; §3.12: a "
       "loader that does not support a required extension must not load the file)"},
      {"BoxTextured-glTF/BoxTextured.gltf", Outcome::Lit, "", ""},
      {"BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb", Outcome::Refused,
       "/accessors/2: POSITION of vertex 0 is -inf (not finite)",
       "invalid: infinite POSITION values (glTF-Validator ACCESSOR_INVALID_FLOAT)"},
      {"ClearCoat-glTF/ClearCoatTest.gltf", Outcome::Lit, "", ""},
      {"IncorrectVertexArrays/Cube.gltf", Outcome::Refused,
       "/meshes/1/primitives/0: 35 vertices, not a multiple of 3 for TRIANGLES",
       "invalid: an index count TRIANGLES cannot take (§3.7.2.1; glTF-Validator "
       "MESH_PRIMITIVE_INCOMPATIBLE_MODE)"},
      {"IndexOutOfRange/AllIndicesOutOfRange.gltf", Outcome::Refused,
       "/accessors/0: index 0 is 65535, the primitive has 24 vertices",
       "invalid: indices past the vertices (§3.7.2.1; glTF-Validator ACCESSOR_INDEX_OOB)"},
      {"IndexOutOfRange/IndexOutOfRange.gltf", Outcome::Refused,
       "/accessors/0: index 0 is 255, the primitive has 24 vertices",
       "invalid: indices past the vertices (§3.7.2.1; glTF-Validator ACCESSOR_INDEX_OOB)"},
      {"MissingBin/BoxTextured.gltf", Outcome::Refused, "/buffers/0:",
       "invalid: its buffer BoxTextured0.bin is not there (glTF-Validator IO_ERROR)"},
      {"RecursiveNodes/RecursiveNodes.gltf", Outcome::Refused,
       "/nodes/1: the node hierarchy is deeper than 1024 (a cycle?)",
       "invalid: a node cycle (§3.5.1: the hierarchy must be disjoint strict trees)"},
      {"SchemaFailures/sceneWrongType.gltf", Outcome::Refused,
       "/buffers/0:", "invalid: \"scene\" is a string (schema) and its buffer is not there"},
      {"TestNoRootNode/NoScene.gltf", Outcome::Refused, "/scenes: the file has no scene to render",
       "invalid: \"scene\": 0 names a scene the file does not have (glTF-Validator "
       "UNRESOLVED_REFERENCE)"},
      {"TestNoRootNode/SceneWithoutNodes.gltf", Outcome::Refused,
       "/scenes/0: the scene has no mesh to render", "valid, no surface: an empty scene"},
      {"cameras/Cameras.gltf", Outcome::Lit, "", ""},
      {"draco/2CylinderEngine.gltf", Outcome::Refused,
       "/extensionsRequired/0: required extension KHR_draco_mesh_compression is not supported",
       "required extension not decoded: KHR_draco_mesh_compression (Debian's tinygltf is built "
       "without Draco)"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_00.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: POINTS carry no surface", "valid, no surface: points only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_01.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: LINES carry no surface", "valid, no surface: lines only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_02.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: LINE_LOOP carry no surface", "valid, no surface: lines only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_03.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: LINE_STRIP carry no surface", "valid, no surface: lines only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_04.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_05.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_06.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_07.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: POINTS carry no surface", "valid, no surface: points only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_08.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: LINES carry no surface", "valid, no surface: lines only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_09.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: LINE_LOOP carry no surface", "valid, no surface: lines only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_10.gltf", Outcome::Refused,
       "/meshes/0/primitives/0/mode: LINE_STRIP carry no surface", "valid, no surface: lines only"},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_11.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_12.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_13.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_14.gltf", Outcome::Lit, "", ""},
      {"glTF-Asset-Generator/Mesh_PrimitiveMode/Mesh_PrimitiveMode_15.gltf", Outcome::Lit, "", ""},
      {"glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf", Outcome::Lit, "", ""},
      // assimp's crash case: the base colour texture reads TEXCOORD_0 (texCoord's default) and
      // the primitive has only TEXCOORD_1.
      {"issue_3269/texcoord_crash.gltf", Outcome::Refused, "/meshes/0/primitives/0: material",
       "invalid: a primitive MUST have the TEXCOORD_n its material's texCoord names "
       "(textureInfo.texCoord, glTF 2.0 schema)"},
      {"simple_skin/simple_skin.gltf", Outcome::Lit, "", ""},
      {"textureTransform/TextureTransformTest.gltf", Outcome::Lit, "", ""},
      {"wrongTypes/badArray.gltf", Outcome::Refused, "/scenes/0: the scene has no mesh to render",
       "invalid: a mesh's \"primitives\" is an object (schema); tinygltf drops the mesh"},
      {"wrongTypes/badExtension.gltf", Outcome::Refused,
       "/materials/0/pbrMetallicRoughness/baseColorTexture/extensions/KHR_texture_transform: "
       "expected an object",
       "invalid: KHR_texture_transform is a string (schema)"},
      // Invalid too (normalTexture.scale is a string, schema); the term reads no normal texture.
      {"wrongTypes/badNumber.gltf", Outcome::Lit, "", ""},
      // Invalid too (pbrMetallicRoughness is an array, schema), but tinygltf reads it as the
      // default material and nothing the term needs is missing.
      {"wrongTypes/badObject.gltf", Outcome::Lit, "", ""},
      // Invalid too (a node's name is a number, schema); tinygltf reads it without the name.
      {"wrongTypes/badString.gltf", Outcome::Lit, "", ""},
      {"wrongTypes/badUint.gltf", Outcome::Refused,
       "/materials/0/pbrMetallicRoughness/baseColorTexture/index: no such texture",
       "invalid: baseColorTexture.index is -1 (schema)"},
  };
  return table;
}

// Covered pixels (alpha > 0) and how many of them are lit (a channel above 0). A scene that
// renders black for want of light has none lit; "lit" asks for more than half, since faces
// turned from both of the rig's lights may be dark where the lobe does not reach.
struct LitCoverage {
  std::size_t covered = 0, lit = 0;
};
LitCoverage coverage(const Image& img) {
  LitCoverage c;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.at(x, y);
      if (p[3] <= 0) continue;
      ++c.covered;
      c.lit += p[0] > 0 || p[1] > 0 || p[2] > 0;
    }
  return c;
}

class DebianGltfModel : public ::testing::TestWithParam<Model> {};

TEST_P(DebianGltfModel, RendersLitOrIsRefusedForItsReason) {
  if (!fs::is_directory(kModels)) GTEST_SKIP() << kModels << " is absent (assimp-testmodels)";
  const Model& m = GetParam();
  const fs::path file = kModels / m.file;
  std::optional<Scene> scene;
  std::string error;
  try {
    scene = load_scene(file);
  } catch (const InputError& e) {
    error = e.what();
  }
  std::string row = "| `" + m.file + "` | ";
  if (m.outcome == Outcome::Refused) {
    EXPECT_FALSE(scene) << m.file << " was expected refused: " << m.why;
    // One line naming the file, then the JSON pointer and the reason.
    EXPECT_EQ(error.rfind(file.string() + ":/", 0), 0u) << m.file << ": " << error;
    EXPECT_NE(error.find(file.string() + ":" + m.reason), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    row += "refused | " + m.why + ": `" + m.reason + "` |";
  } else {
    ASSERT_TRUE(scene) << m.file << ": " << error;
    row += "lit |";
    for (const char* path : {"reference", "gx"}) {
      const LitCoverage c = coverage(render_scene(*scene, path, "", 64, 64));
      EXPECT_GT(c.covered, 0u) << m.file << " " << path;
      EXPECT_GT(c.lit * 2, c.covered)
          << m.file << " " << path << ": " << c.lit << " of " << c.covered << " covered pixels lit";
      row += " " + std::string(path) + " " + std::to_string(c.lit) + "/" +
             std::to_string(c.covered) + " covered pixels lit;";
    }
    row += scene->default_lights.empty() ? " its own lights |" : " default lights |";
  }
  std::cout << row << "\n";
}

TEST(DebianGltfModels, EveryFileIsInTheTable) {
  if (!fs::is_directory(kModels)) GTEST_SKIP() << kModels << " is absent (assimp-testmodels)";
  std::set<std::string> on_disk, in_table;
  for (const auto& e : fs::recursive_directory_iterator(kModels)) {
    const std::string ext = e.path().extension().string();
    if (ext == ".gltf" || ext == ".glb")
      on_disk.insert(fs::relative(e.path(), kModels).generic_string());
  }
  for (const Model& m : models()) in_table.insert(m.file);
  EXPECT_EQ(on_disk, in_table);
}

// examples/debian_engine_jade.json: the engine's materials given translucency by the scene,
// "Material_20" (five glTF materials share the name) by name, every other one by "*".
TEST(DebianGltfModels, TheJadeEngineExampleGivesEveryMaterialTranslucency) {
  if (!fs::is_directory(kModels)) GTEST_SKIP() << kModels << " is absent (assimp-testmodels)";
  const Scene scene = load_scene(test::source_dir() / "examples/debian_engine_jade.json");
  std::size_t by_name = 0;
  for (const Material& m : scene.materials) {
    ASSERT_TRUE(m.translucency) << m.name;
    const bool named = m.name == "Material_20";
    by_name += named;
    EXPECT_EQ(m.translucency->power, named ? 8 : 4) << m.name;
    EXPECT_EQ(m.albedo, named ? m.albedo : glm::dvec3(0.55, 0.8, 0.6)) << m.name;
  }
  EXPECT_GT(by_name, 1u) << "every glTF material of the name is selected";
  const LitCoverage c = coverage(render_scene(scene, "reference", "", 64, 64));
  EXPECT_GT(c.covered, 64u * 64 / 10);
  EXPECT_GT(c.lit * 2, c.covered);
}

// The demo scenes (scenes/*.json: ./run.sh's bench and its report page, the bounds, the
// goldens) hold a real asset with an albedo map (issue 27): a Debian model's baseColorTexture,
// given translucency by the scene. Its lights must show both: the map varies over the covered
// pixels, and the translucency brightens them (the same scene with every translucency_scale 0
// is darker on most of them). scenes/debian_box_textured.json is the one today.
TEST(DebianGltfModels, TheDemoScenesHoldARealAssetWithAnAlbedoMapAndTranslucency) {
  if (!fs::is_directory(kModels)) GTEST_SKIP() << kModels << " is absent (assimp-testmodels)";
  std::vector<std::string> found;
  for (const std::string& file : test::json_files("scenes")) {
    Scene scene = load_scene(test::source_dir() / file);
    bool real = false;
    for (const Material& m : scene.materials) {
      if (!m.albedo_map || !m.translucency) continue;
      if (m.albedo_map->file.string().rfind(kModels.string() + "/", 0) != 0) continue;
      real = true;
      const std::vector<float>& t = m.albedo_map->texture.texels;
      const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
      EXPECT_GT(*hi - *lo, 0.5f) << file << " " << m.name << ": a picture, not a constant";
    }
    if (!real) continue;
    found.push_back(file);
    constexpr int kW = 64, kH = 48;
    const Image lit = render_scene(scene, "reference", "", kW, kH);
    for (Light& l : scene.lights) l.translucency_scale = 0;
    const Image dark = render_scene(scene, "reference", "", kW, kH);
    std::size_t covered = 0, brighter = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const float *a = lit.at(x, y), *b = dark.at(x, y);
        if (a[3] <= 0) continue;
        ++covered;
        brighter += a[0] + a[1] + a[2] > b[0] + b[1] + b[2] + 3 * 8 / 255.0f;  // 8 LSB a channel
      }
    EXPECT_GT(covered, static_cast<std::size_t>(kW * kH / 10)) << file;
    EXPECT_GT(brighter * 2, covered) << file << ": the translucency shows on most covered pixels";
  }
  EXPECT_FALSE(found.empty()) << "no scenes/*.json holds a material with an albedo map from "
                              << kModels << " and a translucency";
}

std::string model_test_name(const ::testing::TestParamInfo<Model>& info) {
  std::string name = info.param.file.substr(info.param.file.rfind('/') + 1);
  std::string out = std::to_string(info.index) + "_";
  for (char c : name) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return out;
}

INSTANTIATE_TEST_SUITE_P(Assimp, DebianGltfModel, ::testing::ValuesIn(models()), model_test_name);

}  // namespace
}  // namespace lt
