// The gx path's transform unit, clipper, setup unit and rasteriser (src/gx/rasteriser.h)
// held to Dolphin's software renderer on frames no demo scene contains (issue 38):
// - DolphinRasterEdges: geometry placed on the rasteriser's own grid, where a rule decides the
//   pixel: vertices on the sample points (the fill rule's ties), edges shared by two triangles,
//   slivers a sixteenth of a pixel wide, triangles that cross the viewport's sides, a huge one,
//   a degenerate one, and a floor that crosses the near plane behind the eye. The same cases
//   against hand-computed answers, without Dolphin: gx_raster_test.cpp.
// - DolphinSeeded: scenes drawn from a fixed seed (a grid of random meshes with random
//   transforms, one to three materials of every thickness source and the maps, one to four mixed
//   lights, a perspective or orthographic camera from a random side), through every gx variant
//   that renders them, plus the scene's exported program edited at random (cull mode, TEV scale
//   and bias, register colours, blend mode, depth compare, the EFB's pixel format and dither)
//   and read back as `--program` reads it.
// Every frame must be Dolphin's to the pixel: ltrender's `:out=xfb` picture of it and Dolphin's
// dump of the FIFO log differ in zero pixels.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <regex>
#include <sstream>

#include "dolphin_util.h"
#include "load/load_scene.h"
#include "paths/gx/c_exporter.h"
#include "paths/gx/gx_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

using test::JudgedFrame;

std::vector<JudgedFrame> every_variant(const Scene& scene) {
  std::vector<JudgedFrame> frames;
  for (const std::string& v : test::judged_variants(scene)) frames.push_back({v, ""});
  return frames;
}

// ---- geometry on the rasteriser's grid ----

// An orthographic camera 240 units high over a 320x240 image: one unit is one pixel, x = 0 is
// the image's centre line (pixel column 160's left edge), y up. Dolphin's rasteriser samples
// pixel column c at screen x = c + 9/16 (rasteriser.h): in these units world x = c - 160 + 9/16.
constexpr double kSample = 9.0 / 16.0;

struct ObjWriter {
  std::ostringstream text;
  int vertices = 0;
  // A triangle wound counter-clockwise as the camera sees it (the scene's front faces), with
  // normals that differ per vertex so that the colours vary across it (interpolation is tested
  // with coverage).
  void triangle(glm::dvec3 a, glm::dvec3 b, glm::dvec3 c) {
    const glm::dvec3 n[3] = {{0.3, 0.1, 1}, {-0.2, 0.4, 1}, {0.1, -0.5, 1}};
    for (const glm::dvec3& p : {a, b, c}) text << "v " << p.x << " " << p.y << " " << p.z << "\n";
    for (const glm::dvec3& m : n) text << "vn " << m.x << " " << m.y << " " << m.z << "\n";
    const int i = vertices + 1;
    text << "f " << i << "//" << i << " " << i + 1 << "//" << i + 1 << " " << i + 2 << "//" << i + 2
         << "\n";
    vertices += 3;
  }
};

std::string edge_case_scene_json(const fs::path& mesh, const std::string& camera) {
  return R"({ "image": { "width": 320, "height": 240, "background": [0.05, 0.1, 0.15] },
  "camera": )" +
         camera + R"(,
  "ambient_light": [0.05, 0.05, 0.05],
  "materials": { "m": { "albedo": [0.8, 0.6, 0.5],
    "translucency": { "power": 3, "distortion": 0.2, "ambient": 0.1, "thickness": 0.5,
                      "tint": [1, 0.5, 0.3] } } },
  "lights": [ { "type": "directional", "direction": [0.3, -0.2, -1], "color": [1, 0.9, 0.8],
                "intensity": 1.3, "translucency_scale": 1 },
              { "type": "directional", "direction": [-0.4, 0.3, 1], "color": [0.5, 0.6, 1],
                "intensity": 1.1, "translucency_scale": 2 } ],
  "objects": [ { "mesh": ")" +
         mesh.string() + R"(", "material": "m" } ] })";
}

constexpr const char* kPixelCamera =
    R"({ "eye": [0, 0, 10], "target": [0, 0, 0], "up": [0, 1, 0], "projection": "orthographic",
       "height": 240, "near": 1, "far": 100 })";

TEST(DolphinRasterEdges, RulesOnTheSampleGridDecideAsDolphinDecides) {
  ObjWriter obj;
  // Column c, row r (top first) of the image, as world x, y at a sample point plus (dx, dy).
  auto at = [](double c, double r, double dx = 0, double dy = 0) {
    return glm::dvec3(c - 160 + kSample + dx, 120 - (r + kSample) - dy, 0);
  };
  // Two triangles sharing a diagonal, every vertex on a sample point: the fill rule decides every
  // pixel on the outer edges and on the diagonal.
  obj.triangle(at(10, 10), at(10, 40), at(40, 40));
  obj.triangle(at(10, 10), at(40, 40), at(40, 10));
  // A fan of six triangles around one sample point: the shared vertex belongs to one of them.
  for (int k = 0; k < 6; ++k) {
    const double a0 = k * 3.14159265358979 / 3, a1 = (k + 1) * 3.14159265358979 / 3;
    const glm::dvec3 centre = at(80, 25);
    obj.triangle(centre, centre + 15.0 * glm::dvec3(std::cos(a0), std::sin(a0), 0),
                 centre + 15.0 * glm::dvec3(std::cos(a1), std::sin(a1), 0));
  }
  // Slivers: a sixteenth of a pixel wide, vertical, horizontal and diagonal; and one whose
  // width straddles a sample column.
  obj.triangle(at(120, 5), at(120, 60), at(120, 60, 1.0 / 16));
  obj.triangle(at(125, 5, -1.0 / 32), at(125, 60, -1.0 / 32), at(125, 60, 1.0 / 32));
  obj.triangle(at(130, 30), at(180, 30, 0, -1.0 / 16), at(180, 30));
  obj.triangle(at(130, 40), at(180, 62), at(180, 62, 1.0 / 16, -1.0 / 16));
  // Crossing the viewport's left, top and right sides: the clipper's planes and the scissor.
  obj.triangle(at(-40, 70), at(30, 110), at(20, 60));
  obj.triangle(at(200, -30), at(230, 40), at(260, 20));
  obj.triangle(at(300, 90), at(360, 130), at(290, 140));
  // Vertices half a sample off the grid either way: rounding to the nearest sixteenth.
  obj.triangle(at(60, 150, 1.0 / 32, 1.0 / 32), at(60, 200, -1.0 / 32, 1.0 / 32),
               at(110, 200, 1.0 / 32, -1.0 / 32));
  // A degenerate triangle (three points on a line) draws nothing, in both.
  obj.triangle(at(150, 150), at(170, 170), at(190, 190));
  // A huge triangle far past every side, behind the others (further from the eye): it covers the
  // rest of the picture through the clipper.
  obj.triangle(glm::dvec3(-1e5, -1e5, -5), glm::dvec3(1e5, -1e5, -5), glm::dvec3(0, 1e5, -5));
  test::TempDir dir;
  test::write_file(dir / "edges.obj", obj.text.str());
  test::write_file(dir / "edges.json", edge_case_scene_json(dir / "edges.obj", kPixelCamera));
  const Scene scene = load_scene(dir / "edges.json");
  test::expect_dolphins_pictures(scene, every_variant(scene), "grid edge cases");
}

// A floor that runs from in front of the camera to far behind it, and a wall one of whose corners
// is behind the eye: the clipper's near plane cuts them (Dolphin clips against w before the
// divide; a vertex behind the eye never reaches the setup unit).
TEST(DolphinRasterEdges, TrianglesCrossingTheNearPlaneAreClippedAsDolphinClips) {
  ObjWriter obj;
  obj.triangle({-6, -1, 6}, {6, -1, 6}, {6, -1, -30});
  obj.triangle({-6, -1, 6}, {6, -1, -30}, {-6, -1, -30});
  obj.triangle({-2, -0.5, 5}, {3, 0.2, -4}, {-1.5, 2.5, -6});
  test::TempDir dir;
  test::write_file(dir / "near.obj", obj.text.str());
  test::write_file(dir / "near.json",
                   edge_case_scene_json(dir / "near.obj", R"({ "eye": [0, 0.5, 4],
      "target": [0, 0, -2], "up": [0, 1, 0], "projection": "perspective", "fov_y_deg": 60,
      "near": 0.5, "far": 60 })"));
  const Scene scene = load_scene(dir / "near.json");
  test::expect_dolphins_pictures(scene, every_variant(scene), "near-plane crossings");
}

// ---- scenes from a fixed seed ----

struct SeededScene {
  std::string json;
  bool perspective = true;
  std::string summary;  // what was drawn, for the table row: "3x3 objects, 2 materials (...), ..."
};

// One random scene: a k x k grid of objects (k in 1..3), each a mesh that suits its material,
// random rotation and scale; materials with constant, rgb, per-vertex or mapped thickness, an
// albedo map, or none at all; one to four lights, directional or point; the camera perspective
// or orthographic from a random direction.
SeededScene seeded_scene(unsigned seed) {
  std::mt19937 rng(seed);
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  auto vec = [&](double lo, double hi) {
    std::ostringstream s;
    s << "[" << uniform(lo, hi) << ", " << uniform(lo, hi) << ", " << uniform(lo, hi) << "]";
    return s.str();
  };
  const fs::path meshes = test::source_dir() / "meshes", maps = test::source_dir() / "scenes/maps";
  auto mesh = [&](const char* name) { return (meshes / name).string(); };

  // Material kinds and the meshes each can draw (vertex thickness needs a baked mesh, a map UVs).
  enum Kind { kConstant, kRgb, kVertex, kThicknessMap, kAlbedoMap, kDiffuse, kKinds };
  const char* const kind_names[kKinds] = {"constant", "rgb",        "vertex",
                                          "map",      "albedo map", "diffuse"};
  const std::vector<std::vector<std::string>> meshes_of = {
      {mesh("cube.ply"), mesh("sphere_s2.ply"), mesh("sphere_s4.ply"), mesh("torus.ply"),
       mesh("blob.ply"), mesh("quad.ply")},
      {mesh("block.ply"), mesh("slab.ply"), mesh("sphere_s3.ply"), mesh("teapot.ply")},
      {mesh("blob_baked.ply"), mesh("block_baked.ply"), mesh("slab_baked.ply"),
       mesh("teapot_baked.ply")},
      {mesh("uvsphere.ply"), mesh("teapot.ply")},
      {mesh("uvsphere.ply"), mesh("teapot_baked.ply")},
      {mesh("sphere_s1.ply"), mesh("torus.ply"), mesh("cube.ply")},
  };
  std::ostringstream j;
  SeededScene out;
  out.perspective = pick(3) != 0;
  const double yaw = uniform(0, 6.2831853), pitch = uniform(-0.9, 0.9), dist = uniform(3.5, 6);
  j << R"({ "image": { "width": 320, "height": 240, "background": )" << vec(0, 0.2) << " },\n";
  j << R"(  "camera": { "eye": [)" << dist * std::cos(pitch) * std::sin(yaw) << ", "
    << dist * std::sin(pitch) << ", " << dist * std::cos(pitch) * std::cos(yaw)
    << "], \"target\": " << vec(-0.3, 0.3) << R"(, "up": [0, 1, 0], )";
  if (out.perspective)
    j << R"("projection": "perspective", "fov_y_deg": )" << uniform(30, 65);
  else
    j << R"("projection": "orthographic", "height": )" << uniform(2.2, 4.5);
  j << R"(, "near": 0.1, "far": 100 },)"
    << "\n";
  if (pick(2)) j << R"(  "ambient_light": )" << vec(0, 0.08) << ",\n";

  const int materials = 1 + pick(3);
  std::vector<Kind> kinds;
  j << R"(  "materials": {)";
  for (int m = 0; m < materials; ++m) {
    const Kind kind = static_cast<Kind>(pick(kKinds));
    kinds.push_back(kind);
    out.summary += std::string(m ? ", " : "") + kind_names[kind];
    j << (m ? ",\n" : "\n") << "    \"m" << m << R"(": { "albedo": )" << vec(0.3, 1);
    if (kind == kAlbedoMap)
      j << R"(, "albedo_map": ")" << (maps / "albedo_checker.png").string() << "\"";
    if (kind != kDiffuse) {
      j << R"(, "translucency": { "power": )" << uniform(1, 12) << R"(, "distortion": )"
        << uniform(0, 0.5) << R"(, "ambient": )" << uniform(0, 0.15) << R"(, "tint": )"
        << vec(0.2, 1) << R"(, "thickness": )";
      if (kind == kRgb)
        j << vec(0.1, 1);
      else if (kind == kVertex)
        j << "\"vertex\"";
      else if (kind == kThicknessMap)
        j << R"({ "texture": ")"
          << (maps / (pick(2) ? "sphere_thickness.png" : "sphere_rgb.png")).string()
          << R"(", "channels": "r" })";
      else
        j << uniform(0.1, 1);
      j << " }";
    }
    j << " }";
  }
  j << "\n  },\n";

  const int lights = 1 + pick(4);
  int point_lights = 0;
  j << R"(  "lights": [)";
  for (int l = 0; l < lights; ++l) {
    j << (l ? ",\n" : "\n");
    const bool point = pick(2) != 0;
    point_lights += point;
    j << R"(    { "type": ")" << (point ? "point" : "directional") << "\", ";
    if (point) {
      j << R"("position": )" << vec(-4, 4) << R"(, "attenuation": { "constant": 1, "linear": )"
        << uniform(0, 0.3) << R"(, "quadratic": )" << uniform(0, 0.4) << " }, ";
    } else {
      j << R"("direction": )" << vec(-1, 1) << ", ";
    }
    j << R"("color": )" << vec(0.3, 1) << R"(, "intensity": )" << uniform(0.4, 2.5)
      << R"(, "translucency_scale": )" << uniform(0, 4) << " }";
  }
  j << "\n  ],\n";

  const int k = 1 + pick(3);
  out.summary = std::to_string(k) + "x" + std::to_string(k) + " objects; " +
                std::to_string(materials) + " materials (" + out.summary + "); " +
                std::to_string(point_lights) + " point, " + std::to_string(lights - point_lights) +
                " directional lights; " + (out.perspective ? "perspective" : "orthographic");
  const double spacing = 2.4 / k;
  j << R"(  "objects": [)";
  for (int n = 0; n < k * k; ++n) {
    const int m = pick(materials);
    const std::vector<std::string>& candidates = meshes_of[kinds[static_cast<size_t>(m)]];
    j << (n ? ",\n" : "\n") << R"(    { "mesh": ")"
      << candidates[pick(static_cast<int>(candidates.size()))] << R"(", "material": "m)" << m
      << R"(", "transform": { "translate": [)" << (n % k - (k - 1) / 2.0) * spacing << ", "
      << (n / k - (k - 1) / 2.0) * spacing << ", " << uniform(-0.3, 0.3) << R"(], "rotate_deg": )"
      << vec(0, 360) << R"(, "scale": )" << uniform(0.35, 0.6) * spacing << " } }";
  }
  j << "\n  ] }\n";
  out.json = j.str();
  return out;
}

// The exported program of `scene`'s default variant, edited as a porter might edit it: each
// choice below is one the emulator models and Dolphin plays.
std::string edited_program(const Scene& scene, unsigned seed, std::string& format_chosen) {
  std::mt19937 rng(seed * 7919u + 1u);
  auto pick = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng); };
  gx::ExportFigures figures;
  figures.scene = "seeded";
  figures.variant = "t=vertex";
  std::string text =
      gx::export_c(gx::scene_programs_for(scene, gx::parse_gx_variant("t=vertex"), ""), figures);
  // Each occurrence replaced on its own, by one of `choices`.
  auto replace_each = [&](const std::string& from, const std::vector<std::string>& choices) {
    std::string result;
    size_t start = 0, at;
    while ((at = text.find(from, start)) != std::string::npos) {
      result += text.substr(start, at - start) +
                choices[static_cast<size_t>(pick(static_cast<int>(choices.size())))];
      start = at + from.size();
    }
    text = result + text.substr(start);
  };
  // Cull mode: GX_Init's back-face culling, or the other face (GX's front faces are clockwise).
  replace_each("GX_SetCullMode(GX_CULL_NONE)",
               {"GX_SetCullMode(GX_CULL_NONE)", "GX_SetCullMode(GX_CULL_BACK)",
                "GX_SetCullMode(GX_CULL_FRONT)"});
  replace_each("GX_CS_SCALE_1", {"GX_CS_SCALE_1", "GX_CS_SCALE_2", "GX_CS_DIVIDE_2"});
  replace_each("GX_TB_ZERO", {"GX_TB_ZERO", "GX_TB_ADDHALF", "GX_TB_SUBHALF"});
  // The blend of the passes after the first: other factors (the destination's alpha among them,
  // which only RGBA6_Z24 stores), subtraction, a logic op.
  replace_each("GX_SetBlendMode(GX_BM_BLEND, GX_BL_ONE, GX_BL_ONE, GX_LO_CLEAR)",
               {"GX_SetBlendMode(GX_BM_BLEND, GX_BL_ONE, GX_BL_ONE, GX_LO_CLEAR)",
                "GX_SetBlendMode(GX_BM_BLEND, GX_BL_DSTALPHA, GX_BL_INVSRCALPHA, GX_LO_CLEAR)",
                "GX_SetBlendMode(GX_BM_BLEND, GX_BL_DSTCLR, GX_BL_INVDSTALPHA, GX_LO_CLEAR)",
                "GX_SetBlendMode(GX_BM_SUBTRACT, GX_BL_ONE, GX_BL_ONE, GX_LO_CLEAR)",
                "GX_SetBlendMode(GX_BM_LOGIC, GX_BL_ONE, GX_BL_ONE, GX_LO_XOR)"});
  // The EFB's pixel format, one for the whole frame (as a game sets it), each pass with the
  // dither on (GX_Init's) or off: RGBA6_Z24 keeps 6 bits and alpha, and dithers.
  const char* const formats[] = {"GX_PF_RGB8_Z24", "GX_PF_RGBA6_Z24", "GX_PF_RGB565_Z16"};
  const std::string format = formats[pick(3)];
  format_chosen = format;
  const std::string set_format = "GX_SetPixelFmt(" + format + ", GX_ZC_LINEAR);\n  ";
  replace_each("GX_SetCullMode(", {set_format + "GX_SetDither(GX_TRUE);\n  GX_SetCullMode(",
                                   set_format + "GX_SetDither(GX_FALSE);\n  GX_SetCullMode("});
  replace_each(
      "GX_SetZMode(GX_TRUE, GX_LEQUAL, GX_TRUE)",
      {"GX_SetZMode(GX_TRUE, GX_LEQUAL, GX_TRUE)", "GX_SetZMode(GX_TRUE, GX_LESS, GX_TRUE)",
       "GX_SetZMode(GX_TRUE, GX_EQUAL, GX_TRUE)"});
  // The register colours a pass loads (the ambient term, the LUT stage's scale).
  std::string result;
  std::smatch m;
  const std::regex colour(R"(GX_SetTevColor\((GX_TEVREG\d), \(GXColor\)\{\d+, \d+, \d+, 255\}\))");
  std::string rest = text;
  while (std::regex_search(rest, m, colour)) {
    result += m.prefix().str() + "GX_SetTevColor(" + m[1].str() + ", (GXColor){" +
              std::to_string(pick(256)) + ", " + std::to_string(pick(256)) + ", " +
              std::to_string(pick(256)) + ", 255})";
    rest = m.suffix().str();
  }
  return result + rest;
}

// Seeds in threes, the three scenes' frames one log (one Dolphin start: a start and stop is
// ~0.7 s whatever the log holds, docs/testing.md "Test time").
constexpr unsigned kSeedsALog = 3;

class DolphinSeeded : public ::testing::TestWithParam<unsigned> {};

TEST_P(DolphinSeeded, EveryFrameIsDolphinsPicture) {
  test::TempDir dir;
  std::vector<SeededScene> seeded;
  std::vector<Scene> scenes;
  std::vector<test::JudgedScene> judged;
  for (unsigned seed = GetParam(); seed < GetParam() + kSeedsALog; ++seed) {
    seeded.push_back(seeded_scene(seed));
    const fs::path file = dir / ("scene" + std::to_string(seed) + ".json");
    test::write_file(file, seeded.back().json);
    scenes.push_back(load_scene(file));
  }
  for (size_t s = 0; s < scenes.size(); ++s) {
    const unsigned seed = GetParam() + static_cast<unsigned>(s);
    const Scene& scene = scenes[s];
    std::vector<JudgedFrame> frames = every_variant(scene);
    const fs::path program = dir / ("edited" + std::to_string(seed) + ".c");
    std::string format;
    test::write_file(program, edited_program(scene, seed, format));
    std::printf("seed %u: the edited program draws in %s\n", seed, format.c_str());
    frames.push_back({"t=vertex", program.string()});
    // The edits must change the picture, or the edited frame would judge nothing new.
    PathOptions edited;
    edited.program_file = program.string();
    const test::PictureDifference change = test::picture_difference(
        render_scene(scene, "gx", "t=vertex", test::kDolphinWidth, test::kDolphinHeight),
        render_scene(scene, "gx", "t=vertex", test::kDolphinWidth, test::kDolphinHeight, edited));
    EXPECT_GT(change.differ, 0u) << "seed " << seed
                                 << ": the edited program draws what the generated one draws";
    judged.push_back({&scene, frames, "seed " + std::to_string(seed) + ": " + seeded[s].summary});
  }
  test::expect_dolphins_pictures(judged);
  if (HasFailure()) {
    for (size_t s = 0; s < seeded.size(); ++s)
      std::printf("seed %u's scene:\n%s\n", GetParam() + static_cast<unsigned>(s),
                  seeded[s].json.c_str());
  }
}

// Seeds 1 to 12.
INSTANTIATE_TEST_SUITE_P(Seeds, DolphinSeeded, ::testing::Range(1u, 13u, kSeedsALog),
                         [](const auto& info) {
                           return "seeds_" + std::to_string(info.param) + "_to_" +
                                  std::to_string(info.param + kSeedsALog - 1);
                         });

}  // namespace
}  // namespace lt
