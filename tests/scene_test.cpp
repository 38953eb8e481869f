// Scene validation: every bad input is one line naming the file and the key, exit 2, and no
// output file; good scenes parse to what the file says.
#include "scene/scene.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "load/load_scene.h"
#include "scene/scene_parse.h"
#include "test_util.h"

namespace lt {
namespace {

const char* kGood = R"({
  "image": {"width": 64, "height": 48, "background": [0, 0, 0]},
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "up": [0, 1, 0],
             "projection": "perspective", "fov_y_deg": 40, "near": 0.1, "far": 100},
  "ambient_light": [0.02, 0.02, 0.02],
  "materials": {
    "marble": {"albedo": [0.9, 0.88, 0.85],
               "translucency": {"power": 8, "distortion": 0.2, "ambient": 0.1,
                                "thickness": [0.5, 0.4, 0.3], "tint": [1, 1, 1],
                                "normalize_distorted_light": false}},
    "plaster": {"albedo": [0.7, 0.7, 0.7]}
  },
  "lights": [
    {"type": "directional", "direction": [0, 0, 2], "color": [1, 1, 1], "intensity": 1,
     "translucency_scale": 2},
    {"type": "point", "position": [0, 1, -2], "color": [1, 0.5, 0.2], "intensity": 3,
     "translucency_scale": 1, "attenuation": {"constant": 1, "linear": 0, "quadratic": 0.25}}
  ],
  "objects": [{"mesh": "quad.obj", "material": "marble",
               "transform": {"translate": [1, 0, 0], "rotate_deg": [0, 90, 0], "scale": 2}}]
})";

class SceneFile : public ::testing::Test {
 protected:
  void SetUp() override { test::write_file(dir_ / "quad.obj", test::quad_obj()); }
  Scene parse(const std::string& text) {
    return load_scene(parse_scene(text, dir_ / "s.json", dir_.path()));
  }
  // Replaces the first occurrence of `from` in the good scene.
  std::string edit(const std::string& from, const std::string& to) {
    std::string s = kGood;
    const size_t pos = s.find(from);
    EXPECT_NE(pos, std::string::npos) << from;
    return s.replace(pos, from.size(), to);
  }
  std::string error_of(const std::string& text) {
    try {
      parse(text);
    } catch (const InputError& e) {
      return e.what();
    }
    return "(no error)";
  }
  test::TempDir dir_;
};

// Parsing reads nothing the scene names (scene/scene_parse.h): a description of a scene whose
// mesh and map are missing is made whole, the files resolved against the scene's folder; loading
// it is what reads them, and names the scene's key of the first file missing.
TEST_F(SceneFile, ParsingReadsNoFileTheSceneNamesLoadingDoes) {
  const std::string text =
      edit("\"plaster\": {\"albedo\": [0.7, 0.7, 0.7]}",
           "\"plaster\": {\"albedo\": [0.7, 0.7, 0.7], \"albedo_map\": \"nowhere.png\"}");
  const std::string missing_mesh = edit("\"mesh\": \"quad.obj\"", "\"mesh\": \"gone.obj\"");
  const SceneDescription d = parse_scene(text, dir_ / "s.json", dir_.path());
  ASSERT_EQ(d.materials.size(), 2u);
  ASSERT_EQ(d.materials[1].maps.size(), 1u);
  EXPECT_EQ(d.materials[1].maps[0].file, dir_.path() / "nowhere.png");
  EXPECT_EQ(d.materials[1].maps[0].key, "materials.plaster.albedo_map");
  EXPECT_FALSE(d.materials[1].material.albedo_map);  // not read
  ASSERT_EQ(d.objects.size(), 1u);
  EXPECT_EQ(d.objects[0].path, dir_.path() / "quad.obj");
  const SceneDescription gone = parse_scene(missing_mesh, dir_ / "s.json", dir_.path());
  EXPECT_EQ(gone.objects[0].path, dir_.path() / "gone.obj");
  try {
    load_scene(d);
    ADD_FAILURE() << "a missing albedo map loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("materials.plaster.albedo_map: albedo map file not found"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NE(error_of(missing_mesh).find("objects[0].mesh: mesh file not found"), std::string::npos)
      << error_of(missing_mesh);
}

TEST_F(SceneFile, GoodSceneParsesToWhatTheFileSays) {
  const Scene s = parse(kGood);
  EXPECT_EQ(s.width, 64);
  ASSERT_EQ(s.materials.size(), 2u);
  const Material& marble = s.materials[0];  // keys are sorted: marble, plaster
  EXPECT_EQ(marble.name, "marble");
  ASSERT_TRUE(marble.translucency);
  EXPECT_EQ(marble.translucency->power, 8);
  EXPECT_EQ(marble.translucency->thickness, glm::dvec3(0.5, 0.4, 0.3));
  EXPECT_FALSE(s.materials[1].translucency);  // plain diffuse: no translucency stage
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].direction, glm::dvec3(0, 0, 1));                 // normalised
  EXPECT_EQ(s.lights[1].color, glm::dvec3(3, 1.5, 0.6000000000000001));  // times intensity
  EXPECT_EQ(s.lights[1].kq, 0.25);
  // Transform: scale 2, rotate 90 about Y, translate +1 in x. Quad vertex (-1,-1,0) ->
  // scaled (-2,-2,0) -> rotated (0,-2,2) -> translated (1,-2,2).
  const glm::dvec3 p = s.objects[0].mesh.positions[0];
  EXPECT_NEAR(p.x, 1, 1e-12);
  EXPECT_NEAR(p.y, -2, 1e-12);
  EXPECT_NEAR(p.z, 2, 1e-12);
  // The normal (0,0,1) rotates to (1,0,0) and stays unit under the uniform scale.
  const glm::dvec3 n = s.objects[0].mesh.normals[0];
  EXPECT_NEAR(n.x, 1, 1e-12);
  EXPECT_NEAR(glm::length(n), 1, 1e-12);
  const SceneNeeds needs = scene_needs(s);
  EXPECT_EQ(needs.directional_lights, 1);
  EXPECT_EQ(needs.point_lights, 1);
  EXPECT_TRUE(needs.any_translucency);
  EXPECT_FALSE(needs.any_vertex_thickness);
}

struct BadSceneCase {
  const char* name;
  const char* from;
  const char* to;
  const char* expect_in_message;
};

void PrintTo(const BadSceneCase& c, std::ostream* os) {
  *os << c.name;
}

const BadSceneCase kBad[] = {
    {"unknown_top_key", "\"ambient_light\"", "\"ambient_lihgt\"", "ambient_lihgt: unknown key"},
    {"unknown_material_key", "\"albedo\": [0.9", "\"albedoo\": [0.9",
     "materials.marble.albedoo: unknown key"},
    {"negative_power", "\"power\": 8", "\"power\": -1",
     "materials.marble.translucency.power: out of range"},
    {"power_as_string", "\"power\": 8", "\"power\": \"8\"",
     "materials.marble.translucency.power: expected a number"},
    {"bad_thickness_word", "\"thickness\": [0.5, 0.4, 0.3]", "\"thickness\": \"vertexx\"",
     "materials.marble.translucency.thickness"},
    {"negative_scale", "\"translucency_scale\": 2", "\"translucency_scale\": -2",
     "lights[0].translucency_scale: out of range"},
    {"bad_light_type", "\"type\": \"directional\"", "\"type\": \"spot\"", "lights[0].type"},
    {"zero_direction", "\"direction\": [0, 0, 2]", "\"direction\": [0, 0, 0]",
     "lights[0].direction: must not be zero"},
    {"short_colour", "\"color\": [1, 1, 1]", "\"color\": [1, 1]", "lights[0].color"},
    {"zero_attenuation", "\"constant\": 1, \"linear\": 0, \"quadratic\": 0.25",
     "\"constant\": 0, \"linear\": 0, \"quadratic\": 0", "lights[1].attenuation"},
    {"unknown_material_ref", "\"material\": \"marble\"", "\"material\": \"marbel\"",
     "objects[0].material: unknown material"},
    {"missing_mesh", "\"mesh\": \"quad.obj\"", "\"mesh\": \"nope.obj\"", "nope.obj"},
    // The system calls stop at the NUL: it read quad.obj.
    {"nul_in_mesh_path", "\"mesh\": \"quad.obj\"", "\"mesh\": \"quad.obj\\u0000.ply\"",
     "objects[0].mesh: a path cannot contain a NUL byte: \"quad.obj\\u0000.ply\""},
    {"width_zero", "\"width\": 64", "\"width\": 0", "image.width: out of range"},
    {"far_before_near", "\"far\": 100", "\"far\": 0.01", "camera.far"},
    {"bad_projection", "\"perspective\"", "\"fisheye\"", "camera.projection"},
    {"up_parallel", "\"up\": [0, 1, 0]", "\"up\": [0, 0, 1]", "camera.up"},
    {"vertex_thickness_without_colours", "\"thickness\": [0.5, 0.4, 0.3]",
     "\"thickness\": \"vertex\"", "has no vertex colours"},
    // Magnitude limits keep every product of the equation finite in float (scene.cpp).
    {"albedo_beyond_float_safe", "\"albedo\": [0.9, 0.88, 0.85]", "\"albedo\": [1e300, 0.88, 0.85]",
     "materials.marble.albedo: component out of range"},
    // The scalar thickness takes the rgb form's bound: 1e300 made the reference's pixels Inf.
    {"scalar_thickness_beyond_float_safe", "\"thickness\": [0.5, 0.4, 0.3]", "\"thickness\": 1e300",
     "materials.marble.translucency.thickness: out of range: 1e+300 (allowed [0.0, 10000.0])"},
    {"scalar_thickness_beyond_float", "\"thickness\": [0.5, 0.4, 0.3]", "\"thickness\": 3.5e38",
     "materials.marble.translucency.thickness: out of range"},
    {"negative_scalar_thickness", "\"thickness\": [0.5, 0.4, 0.3]", "\"thickness\": -0.5",
     "materials.marble.translucency.thickness: out of range"},
    {"number_overflow", "\"power\": 8", "\"power\": 1e400",
     "s.json: invalid JSON: number overflow"},
    {"eye_too_far", "\"eye\": [0, 0, 4]", "\"eye\": [0, 0, 4e12]",
     "camera.eye: component out of range"},
    {"syntax_error_line", "\"lights\": [", "\"lights\": [,", "s.json:13: invalid JSON"},
};

class BadScene : public SceneFile, public ::testing::WithParamInterface<BadSceneCase> {};

TEST_P(BadScene, NamesTheFileAndTheKey) {
  const BadSceneCase& c = GetParam();
  const std::string msg = error_of(edit(c.from, c.to));
  EXPECT_NE(msg.find(c.expect_in_message), std::string::npos) << msg;
  EXPECT_NE(msg.find("s.json"), std::string::npos) << msg;
}

INSTANTIATE_TEST_SUITE_P(Validation, BadScene, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return std::string(info.param.name); });

TEST_F(SceneFile, CliReportsOneLineExitTwoAndWritesNothing) {
  test::write_file(dir_ / "bad.json", edit("\"power\": 8", "\"power\": -3"));
  const auto out = dir_ / "out.png";
  const auto r = test::run_ltrender("render " + (dir_ / "bad.json").string() + " --path glsl -o " +
                                    out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u) << r.err;
  EXPECT_NE(r.err.find("bad.json:materials.marble.translucency.power"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(SceneFile, CliRejectsUnknownPathAndVariantAndMissingScene) {
  test::write_file(dir_ / "good.json", kGood);
  const std::string scene = (dir_ / "good.json").string();
  const auto out = dir_ / "out.png";
  auto r = test::run_ltrender("render " + scene + " --path glsll -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("unknown path"), std::string::npos) << r.err;
  r = test::run_ltrender("render " + scene + " --path glsl --variant pow=nope -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("no such variant"), std::string::npos) << r.err;
  r = test::run_ltrender("render " + (dir_ / "missing.json").string() + " --path glsl -o " +
                         out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("missing.json: file not found"), std::string::npos) << r.err;
  r = test::run_ltrender("render " + scene + " --path glsl -o " + (dir_ / "out.jpg").string());
  EXPECT_EQ(r.exit_code, 2);
  r = test::run_ltrender("render " + scene + " --path glsl --width -5 -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  // Within each side's range but too many pixels in all: refused before any allocation, naming
  // the options (not the scene's image key) and the real limit, a pixel count.
  r = test::run_ltrender("render " + scene + " --path reference --width 16384 --height 16384 -o " +
                         out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err,
            "ltrender: error: --width/--height: 16384x16384 is 268435456 pixels, over the limit of "
            "16777216 (4096^2; the reference needs ~100 bytes a pixel)\n");
  // One option: the other side is the scene's (48); 8192 x 4096 would pass a per-side limit.
  r = test::run_ltrender("render " + scene + " --path reference --width 16384 --height 4096 -o " +
                         out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err.rfind("ltrender: error: --width/--height: 16384x4096 is 67108864 pixels", 0), 0u)
      << r.err;
  r = test::run_ltrender("render " + scene + " --path reference --width 16384 -o " + out.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;  // 16384x48 is within the limit
  fs::remove(out);
  EXPECT_FALSE(fs::exists(out));
}

// A triangle whose second vertex has float colour (`red`, 0.5, 0.5).
std::string coloured_triangle(const std::string& red) {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
         "property float z\nproperty float red\nproperty float green\nproperty float blue\n"
         "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
         "-1 -1 0 0.5 0.5 0.5\n1 -1 0 " +
         red + " 0.5 0.5\n0 1 0 0.5 0.5 0.5\n3 0 1 2\n";
}

// Vertex colours that are the thickness are bounded like the scalar: 3e38 made Inf pixels, and
// bench aborted on the reference's Inf (compare.cpp's CHECK).
TEST_F(SceneFile, VertexThicknessColoursAreBoundedLikeTheScalar) {
  std::string scene = edit("\"thickness\": [0.5, 0.4, 0.3]", "\"thickness\": \"vertex\"");
  scene.replace(scene.find("quad.obj"), 8, "tri.ply");
  test::write_file(dir_ / "s.json", scene);
  for (const std::string& red : {"3e38", "-0.25"}) {
    test::write_file(dir_ / "tri.ply", coloured_triangle(red));
    for (const std::string& cmd : {"render " + (dir_ / "s.json").string() +
                                       " --path reference -o " + (dir_ / "out.exr").string(),
                                   "bench " + (dir_ / "s.json").string() + " --paths glsl -o " +
                                       (dir_ / "bench").string()}) {
      const auto r = test::run_ltrender(cmd);
      EXPECT_EQ(r.exit_code, 2) << cmd << ": " << r.err;
      EXPECT_EQ(r.err.rfind("ltrender: error: " + (dir_ / "s.json").string() +
                                ":objects[0].mesh: vertex 1 of " + (dir_ / "tri.ply").string() +
                                " has colour component ",
                            0),
                0u)
          << r.err;
      EXPECT_NE(r.err.find("out of range for \"thickness\": \"vertex\" (allowed [0.0, 10000.0])"),
                std::string::npos)
          << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
    EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
    EXPECT_FALSE(fs::exists(dir_ / "bench"));
  }
  // In range: renders.
  test::write_file(dir_ / "tri.ply", coloured_triangle("10000"));
  const auto r = test::run_ltrender("render " + (dir_ / "s.json").string() +
                                    " --path reference -o " + (dir_ / "out.exr").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// The scalar form through the commands that misbehaved: no Inf reference, no multi-kilobyte
// arbfp error, no SIGABRT from bench.
TEST_F(SceneFile, HugeScalarThicknessIsOneLineForEveryCommand) {
  test::write_file(dir_ / "s.json", edit("\"thickness\": [0.5, 0.4, 0.3]", "\"thickness\": 1e300"));
  const std::string scene = (dir_ / "s.json").string();
  for (const std::string& cmd :
       {"render " + scene + " --path reference -o " + (dir_ / "out.exr").string(),
        "render " + scene + " --path arbfp -o " + (dir_ / "out.png").string(),
        "bench " + scene + " --paths glsl -o " + (dir_ / "bench").string()}) {
    const auto r = test::run_ltrender(cmd);
    EXPECT_EQ(r.exit_code, 2) << cmd << ": " << r.err;
    EXPECT_EQ(r.err.rfind("ltrender: error: " + scene +
                              ":materials.marble.translucency.thickness: out of range",
                          0),
              0u)
        << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out.exr"));
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
  EXPECT_FALSE(fs::exists(dir_ / "bench"));
}

// The message was cut at the NUL ("mesh file not found: .../nope"): all of it is one line now.
TEST_F(SceneFile, NulInAMeshPathIsOneWholeLine) {
  test::write_file(dir_ / "s.json",
                   edit("\"mesh\": \"quad.obj\"", "\"mesh\": \"nope\\u0000.obj\""));
  const auto r = test::run_ltrender("info " + (dir_ / "s.json").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ltrender: error: " + (dir_ / "s.json").string() +
                       ":objects[0].mesh: a path cannot contain a NUL byte: \"nope\\u0000.obj\"\n");
}

TEST_F(SceneFile, ImageTooLargeNamesTheImageKeyAndThePixelLimit) {
  std::string text = edit("\"width\": 64", "\"width\": 8192");
  text.replace(text.find("\"height\": 48"), 12, "\"height\": 8192");
  test::write_file(dir_ / "big.json", text);
  const auto r = test::run_ltrender("render " + (dir_ / "big.json").string() + " --path flat -o " +
                                    (dir_ / "out.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ltrender: error: " + (dir_ / "big.json").string() +
                       ":image: 8192x8192 is 67108864 pixels, over the limit of 16777216 (4096^2; "
                       "the reference needs ~100 bytes a pixel)\n");
  EXPECT_FALSE(fs::exists(dir_ / "out.png"));
}

TEST_F(SceneFile, CliNeverOverwritesAnInput) {
  test::write_file(dir_ / "good.json", kGood);
  const auto before = std::filesystem::file_size(dir_ / "quad.obj");
  // An output named like an input mesh (with an image extension it would still be refused:
  // here the scene file itself, renamed to .png, is the input).
  test::write_file(dir_ / "scene.png", kGood);
  const auto r = test::run_ltrender("render " + (dir_ / "scene.png").string() + " --path glsl -o " +
                                    (dir_ / "scene.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("overwrite an input"), std::string::npos) << r.err;
  EXPECT_EQ(std::filesystem::file_size(dir_ / "quad.obj"), before);
  EXPECT_EQ(test::run_ltrender("info " + (dir_ / "scene.png").string()).exit_code, 0);
}

}  // namespace
}  // namespace lt

namespace lt {
namespace {

// docs/input-files.md "Scene limits": the counts a scene may ask for, refused at parse time with
// the key, and the largest allowed count still parses.
std::string repeated(const std::string& element, std::size_t n) {
  std::string s;
  for (std::size_t i = 0; i < n; ++i) s += (i ? "," : "") + element;
  return s;
}

TEST_F(SceneFile, CountLimitsAreCheckedWithTheKey) {
  const std::string light =
      R"({"type": "directional", "direction": [0, 0, 1], "color": [1, 1, 1]})";
  const std::string lights_from = R"("lights": [)";
  const std::size_t lights_at = std::string(kGood).find(lights_from);
  const std::size_t lights_end = std::string(kGood).find("],\n  \"objects\"");
  auto with_lights = [&](std::size_t n) {
    std::string s = kGood;
    return s.replace(lights_at, lights_end - lights_at, lights_from + repeated(light, n));
  };
  EXPECT_EQ(parse(with_lights(64)).lights.size(), 64u);
  EXPECT_NE(error_of(with_lights(65)).find("s.json:lights: 65 lights, more than the limit of 64"),
            std::string::npos)
      << error_of(with_lights(65));

  const std::string object = R"({"mesh": "quad.obj", "material": "plaster"})";
  const std::string objects_from = R"("objects": [)";
  auto with_objects = [&](std::size_t n) {
    std::string s = kGood;
    const std::size_t at = s.find(objects_from);
    return s.replace(at, s.rfind(']') - at, objects_from + repeated(object, n));
  };
  EXPECT_EQ(parse(with_objects(1024)).objects.size(), 1024u);
  EXPECT_NE(error_of(with_objects(1025)).find("s.json:objects: 1025 objects, more than the limit"),
            std::string::npos)
      << error_of(with_objects(1025));

  std::string many_materials = "\"materials\": {";
  for (int i = 0; i < 257; ++i)
    many_materials += (i ? "," : "") + std::string("\"m") + std::to_string(i) + "\": {}";
  std::string s = kGood;
  const std::size_t at = s.find("\"materials\": {");
  s.replace(at, std::string("\"materials\": {").size(), many_materials + ",");
  EXPECT_NE(error_of(s).find("s.json:materials: 259 materials, more than the limit of 256"),
            std::string::npos)
      << error_of(s);
}

}  // namespace
}  // namespace lt
