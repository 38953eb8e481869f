// Primitive modes (glTF 2.0 §3.7.2.1): strips and fans are the triangles the spec's formulas
// give, and render exactly as the same quad written as a triangle list; points and lines are
// skipped with one warning line, refused only when nothing else is left.
#include "load/gltf/gltf_topology.h"

#include <gtest/gtest.h>

#include "gltf_test_util.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "scene/scene.h"

namespace lt {
namespace {

using json = nlohmann::json;
using Triangles = std::vector<glm::uvec3>;

TEST(GltfTopology, StripAndFanFollowTheSpecFormulas) {
  // Strip p_i = {v_i, v_i+(1+i%2), v_i+(2-i%2)}: the odd triangle {11, 13, 12} is GL's
  // {12, 11, 13} rotated, the same winding.
  EXPECT_EQ(*gltf::assemble_triangles(5, {10, 11, 12, 13, 14}),
            (Triangles{{10, 11, 12}, {11, 13, 12}, {12, 13, 14}}));
  // Fan p_i = {v_i+1, v_i+2, v_0}.
  EXPECT_EQ(*gltf::assemble_triangles(6, {10, 11, 12, 13}),
            (Triangles{{11, 12, 10}, {12, 13, 10}}));
  EXPECT_EQ(*gltf::assemble_triangles(4, {1, 2, 3, 4, 5, 6}), (Triangles{{1, 2, 3}, {4, 5, 6}}));
  // Counts the mode cannot take.
  EXPECT_FALSE(gltf::assemble_triangles(4, {0, 1, 2, 3}));
  EXPECT_FALSE(gltf::assemble_triangles(5, {0, 1}));
  EXPECT_FALSE(gltf::assemble_triangles(6, {0, 1}));
  EXPECT_TRUE(gltf::carries_surface(5) && gltf::carries_surface(6) && gltf::carries_surface(4));
  for (int mode = 0; mode <= 3; ++mode) EXPECT_FALSE(gltf::carries_surface(mode)) << mode;
}

// The unit quad's corners, counter-clockwise seen from +Z.
const float kCorner[4][3] = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};

// A quad drawn with `mode` over the corners `order` (indexed: all four corners stored once and
// `order` as u16 indices; not indexed: the corners stored in `order`). No NORMAL: the importer
// computes it from the winding, so a wrongly wound triangle faces away from the light and is
// black. A directional light travels -Z onto it from the camera's side.
test::GltfWriter quad(int mode, const std::vector<std::uint16_t>& order, bool indexed) {
  test::GltfWriter w;
  std::vector<float> positions;
  json prim = {{"mode", mode}};
  if (indexed) {
    for (const auto& c : kCorner) positions.insert(positions.end(), c, c + 3);
    prim["attributes"]["POSITION"] = w.floats(positions, "VEC3", 3);
    prim["indices"] = w.accessor(order, 5123, "SCALAR", 1);
  } else {
    for (std::uint16_t i : order) positions.insert(positions.end(), kCorner[i], kCorner[i] + 3);
    prim["attributes"]["POSITION"] = w.floats(positions, "VEC3", 3);
  }
  w.doc["materials"].push_back(
      {{"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.6, 0.4, 1}}}}});
  prim["material"] = 0;
  w.doc["meshes"].push_back({{"name", "quad"}, {"primitives", {prim}}});
  w.root({{"mesh", 0}});
  w.light({{"type", "directional"}, {"intensity", 3.14159265358979323846}});
  w.doc["cameras"].push_back(
      {{"type", "orthographic"},
       {"orthographic", {{"xmag", 1.5}, {"ymag", 1.5}, {"znear", 0.1}, {"zfar", 10}}}});
  w.root({{"camera", 0}, {"translation", {0, 0, 3}}});
  return w;
}

struct Topology {
  std::string name;
  int mode;
  std::vector<std::uint16_t> order;
  bool indexed;
};

TEST(GltfTopology, StripAndFanQuadsRenderAsTheTriangleListQuadOnReferenceAndGx) {
  test::TempDir dir;
  const Scene list = load_scene(quad(4, {0, 1, 2, 0, 2, 3}, true).write_gltf(dir.path(), "list"));
  const std::vector<Topology> others = {
      {"strip_indexed", 5, {0, 1, 3, 2}, true},
      {"strip", 5, {0, 1, 3, 2}, false},
      {"fan_indexed", 6, {0, 1, 2, 3}, true},
      {"fan", 6, {0, 1, 2, 3}, false},
  };
  for (const char* path : {"reference", "gx"}) {
    const Image want = render_scene(list, path, "", 64, 64);
    // The list quad itself is lit where it covers: the comparison below compares something.
    const float* centre = want.at(32, 32);
    ASSERT_GT(centre[0], 0.5f) << path;
    ASSERT_EQ(want.at(0, 0)[3], 0.0f) << path << ": the quad should not cover the corner";
    for (const Topology& t : others) {
      const Scene s = load_scene(quad(t.mode, t.order, t.indexed).write_gltf(dir.path(), t.name));
      ASSERT_EQ(s.objects.at(0).mesh.triangles.size(), 2u) << t.name;
      const Image got = render_scene(s, path, "", 64, 64);
      EXPECT_EQ(got.rgba, want.rgba) << path << " " << t.name;
    }
  }
}

TEST(GltfTopology, LinesAndPointsAreSkippedWithOneWarningLine) {
  test::TempDir dir;
  test::GltfWriter w = quad(4, {0, 1, 2, 0, 2, 3}, true);
  // Two more primitives of the same vertices: a line loop and points.
  json lines = w.doc["meshes"][0]["primitives"][0];
  lines["mode"] = 2;
  json points = lines;
  points["mode"] = 0;
  w.doc["meshes"][0]["primitives"].push_back(lines);
  w.doc["meshes"][0]["primitives"].push_back(points);
  const fs::path file = w.write_gltf(dir.path(), "mixed");
  const Scene scene = load_scene(file);
  EXPECT_EQ(scene.objects.size(), 1u);
  ASSERT_EQ(scene.warnings.size(), 1u);
  EXPECT_NE(scene.warnings[0].find("/meshes/0/primitives/1 (mesh \"quad\", LINE_LOOP), "
                                   "/meshes/0/primitives/2 (mesh \"quad\", POINTS)"),
            std::string::npos)
      << scene.warnings[0];
  const auto r = test::run_ltrender("render " + file.string() +
                                    " --path reference --width 32 --height 32 -o " +
                                    (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "ltrender: warning: " + scene.warnings[0] + "\n");
}

TEST(GltfTopology, OnlyLinesIsRefusedNamingTheFirstOnesMode) {
  test::TempDir dir;
  test::GltfWriter w = quad(1, {0, 1, 1, 2, 2, 3, 3, 0}, true);
  const fs::path file = w.write_gltf(dir.path(), "wire");
  const auto r = test::run_ltrender("render " + file.string() + " --path reference -o " +
                                    (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(
      r.err.rfind("ltrender: error: " + file.string() + ":/meshes/0/primitives/0/mode: LINES", 0),
      0u)
      << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out.png"));
}

TEST(GltfTopology, AStripOfTwoIndicesIsRefusedNamingThePrimitive) {
  test::TempDir dir;
  const fs::path file = quad(5, {0, 1}, true).write_gltf(dir.path(), "short");
  const auto r = test::run_ltrender("info " + file.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ltrender: error: " + file.string() +
                       ":/meshes/0/primitives/0: 2 indices, fewer than the 3 a TRIANGLE_STRIP "
                       "needs\n");
}

}  // namespace
}  // namespace lt
