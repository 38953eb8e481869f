// Bad glTF files through the binary: exit 2 and one stderr line naming the file and the JSON
// pointer (cli.md), never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gltf_test_util.h"

namespace lt {
namespace {

using json = nlohmann::json;

struct BadFile {
  std::string name;
  std::string where;  // expected after "FILE:"
  std::string what;   // a piece of the message
};

void PrintTo(const BadFile& b, std::ostream* os) {
  *os << b.name;
}

// Writes the bad file of `name` into `dir` and returns it.
fs::path write_bad(const std::string& name, const fs::path& dir) {
  test::GltfWriter w = test::volume_quad();
  if (name == "truncated_glb") {
    const std::string bytes = w.glb_bytes();
    test::write_file(dir / "bad.glb", bytes.substr(0, bytes.size() - 10));
    return dir / "bad.glb";
  }
  if (name == "json_syntax_error") {
    // The JSON breaks on line 3: the message names that line, as a scene file's does.
    test::write_file(dir / "bad.gltf",
                     "{\n  \"asset\": {\"version\": \"2.0\"},\n  \"meshes\": [,\n}\n");
    return dir / "bad.gltf";
  }
  if (name == "accessor_beyond_view") {
    w.doc["accessors"][0]["count"] = 5;  // 5 x 12 bytes in a 48-byte view
  } else if (name == "view_beyond_buffer") {
    w.doc["bufferViews"][0]["byteLength"] = 4096;
  } else if (name == "nan_position") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&w.bin[4], &nan, 4);
  } else if (name == "missing_buffer") {
    const fs::path p = w.write_gltf(dir, "bad");
    fs::remove(dir / "bad.bin");
    return p;
  } else if (name == "unknown_required_extension") {
    w.doc["extensionsRequired"] = {"KHR_materials_volume", "EXT_meshopt_compression"};
  } else if (name == "spot_light") {
    w.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["type"] = "spot";
    w.doc["extensions"]["KHR_lights_punctual"]["lights"][0]["spot"] = json::object();
  } else if (name == "line_mode") {
    w.doc["meshes"][0]["primitives"][0]["mode"] = 1;
  } else if (name == "base_colour_texture") {
    w.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {{"index", 0}};
    w.doc["textures"] = json::array({json::object()});
  } else if (name == "index_out_of_range") {
    std::uint16_t nine = 9;
    std::memcpy(&w.bin[96 + 2], &nine, 2);  // positions 48 + normals 48, then the indices
  }
  return w.write_gltf(dir, "bad");
}

class GltfBadFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(GltfBadFile, ExitsTwoWithOneLineNamingTheFileAndThePointer) {
  test::TempDir dir;
  const fs::path file = write_bad(GetParam().name, dir.path());
  const auto r = test::run_ltrender("render " + file.string() + " --path reference -o " +
                                    (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  const std::string expected = "ltrender: error: " + file.string() + ":" + GetParam().where + ": ";
  EXPECT_EQ(r.err.rfind(expected, 0), 0u) << r.err;
  EXPECT_NE(r.err.find(GetParam().what), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

INSTANTIATE_TEST_SUITE_P(
    Gltf, GltfBadFile,
    ::testing::Values(
        BadFile{"truncated_glb", "(GLB header)", "truncated"},
        BadFile{"json_syntax_error", "3", "invalid JSON: parse error at line 3"},
        BadFile{"accessor_beyond_view", "/accessors/0", "buffer view 0 has 48"},
        BadFile{"view_beyond_buffer", "/bufferViews/0", "beyond buffer 0"},
        BadFile{"nan_position", "/accessors/0", "not finite"},
        BadFile{"missing_buffer", "/buffers/0", "file not found"},
        BadFile{"unknown_required_extension", "/extensionsRequired/1", "EXT_meshopt_compression"},
        BadFile{"spot_light", "/extensions/KHR_lights_punctual/lights/0/type", "spot lights"},
        BadFile{"line_mode", "/meshes/0/primitives/0/mode", "LINES"},
        BadFile{"base_colour_texture", "/textures/0", "has no source image"},
        BadFile{"index_out_of_range", "/accessors/2", "index 1 is 9"}),
    [](const auto& info) { return info.param.name; });

TEST(GltfCommands, InfoListsTheMappingAndEveryCommandTakesAGltfScene) {
  test::TempDir dir;
  const fs::path file = test::volume_quad().write_glb(dir.path(), "quad");
  const auto info = test::run_ltrender("info " + file.string());
  EXPECT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("glTF import"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("mapped /materials/0/extensions/KHR_materials_volume"), std::string::npos)
      << info.out;
  const auto render = test::run_ltrender("render " + file.string() +
                                         " --path glsl --camera front --width 32 --height 24 -o " +
                                         (dir / "out.png").string());
  EXPECT_EQ(render.exit_code, 0) << render.err;
  EXPECT_TRUE(fs::exists(dir / "out.png"));
  const auto camera = test::run_ltrender(
      "render " + file.string() + " --path glsl --camera nope -o " + (dir / "x.png").string());
  EXPECT_EQ(camera.exit_code, 2);
  EXPECT_EQ(camera.err.rfind("ltrender: error: --camera:nope: ", 0), 0u) << camera.err;
  const auto exported =
      test::run_ltrender("export gx " + file.string() + " -o " + (dir / "p.c").string());
  EXPECT_EQ(exported.exit_code, 0) << exported.err;
}

}  // namespace
}  // namespace lt
