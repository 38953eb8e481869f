// Texture coordinates from every mesh format: hand-written fixtures in tests/data/meshes/uv/
// whose values are read back exactly, a UV seam in an OBJ split into its own vertex, bad UVs as
// one InputError naming the file and line, and a PLY round trip that keeps them.
#include <gtest/gtest.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/build_paths.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/meshgen.h"
#include "test_util.h"

namespace lt {
namespace {

using OpenMesh::IO::Options;

const fs::path kUv = lt::build_paths::source_dir() / "tests" / "data" / "meshes" / "uv";

// The UV of the mesh vertex at `position` (the fixtures have one vertex per position unless a
// seam splits it: then all of them, in index order).
std::vector<glm::dvec2> uvs_at(const TriangleMesh& m, const glm::dvec3& position) {
  std::vector<glm::dvec2> out;
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    if (m.positions[i] == position) out.push_back(m.uvs[i]);
  }
  return out;
}

TEST(MeshUvs, PlyFloatUvAreExactAndOtherPropertiesStayExtras) {
  const LoadedMesh loaded = read_mesh(kUv / "quad_uv.ply");
  EXPECT_TRUE(loaded.read_options.vertex_has_texcoord());
  ASSERT_EQ(loaded.extra_vertex_properties.size(), 1u);
  EXPECT_EQ(loaded.extra_vertex_properties[0].name, "quality");
  const TriangleMesh m = to_triangle_mesh(loaded);
  EXPECT_EQ(m.uvs,
            (std::vector<glm::dvec2>{{0.125, 0.0}, {0.625, 0.0}, {0.625, 0.25}, {0.125, 0.25}}));
}

TEST(MeshUvs, PlyDoubleStKeepTheirDoubles) {
  const TriangleMesh m = load_triangle_mesh(kUv / "quad_st.ply");
  ASSERT_EQ(m.uvs.size(), 4u);
  // 0.1 is no float: the double the file wrote is what comes back.
  EXPECT_EQ(m.uvs[0], glm::dvec2(0.1, 0.2));
  EXPECT_EQ(m.uvs[2], glm::dvec2(0.3, 0.7));
}

TEST(MeshUvs, PlyTextureUvWinsOverAnIntegerU) {
  const LoadedMesh loaded = read_mesh(kUv / "quad_texture_uv.ply");
  ASSERT_EQ(loaded.extra_vertex_properties.size(), 1u);
  EXPECT_EQ(loaded.extra_vertex_properties[0].name, "u");
  EXPECT_EQ(loaded.extra_vertex_properties[0].values, (std::vector<double>{7, 8, 9}));
  const TriangleMesh m = to_triangle_mesh(loaded);
  ASSERT_EQ(m.uvs.size(), 3u);
  EXPECT_EQ(m.uvs[1], glm::dvec2(1.0, 0.75));
  EXPECT_EQ(m.uvs[2], glm::dvec2(0.5, 1.0));
}

TEST(MeshUvs, MeshWithoutUvsHasNone) {
  const TriangleMesh m = load_triangle_mesh(lt::build_paths::source_dir() / "meshes" / "cube.ply");
  EXPECT_TRUE(m.uvs.empty());
}

TEST(MeshUvs, ObjSeamSplitsTheVertexKeepingItsNormal) {
  const TriangleMesh m = load_triangle_mesh(kUv / "seam.obj");
  // 4 positions, one of them on a seam: 5 vertices.
  ASSERT_EQ(m.positions.size(), 5u);
  ASSERT_EQ(m.uvs.size(), 5u);
  ASSERT_EQ(m.triangles.size(), 2u);
  const auto corner = uvs_at(m, {0, 0, 0});
  ASSERT_EQ(corner.size(), 2u);
  EXPECT_EQ(corner[0], glm::dvec2(0.0, 0.0));  // the first face's UV stays with the original
  EXPECT_EQ(corner[1], glm::dvec2(0.75, 0.25));
  // The same value through two vt records is no seam.
  EXPECT_EQ(uvs_at(m, {1, 1, 0}), std::vector<glm::dvec2>{glm::dvec2(0.5, 0.5)});
  EXPECT_EQ(uvs_at(m, {1, 0, 0}), std::vector<glm::dvec2>{glm::dvec2(0.5, 0.0)});
  EXPECT_EQ(uvs_at(m, {0, 1, 0}), std::vector<glm::dvec2>{glm::dvec2(0.25, 0.5)});
  for (const auto& n : m.normals) EXPECT_EQ(n, glm::dvec3(0, 0, 1));
  // Each triangle's corners carry the UVs its face named.
  for (const auto& t : m.triangles) {
    bool second_face = false;
    for (int k = 0; k < 3; ++k) second_face |= m.uvs[t[k]] == glm::dvec2(0.25, 0.5);
    for (int k = 0; k < 3; ++k) {
      if (m.positions[t[k]] == glm::dvec3(0, 0, 0)) {
        EXPECT_EQ(m.uvs[t[k]], second_face ? glm::dvec2(0.75, 0.25) : glm::dvec2(0.0, 0.0));
      }
    }
  }
}

TEST(MeshUvs, OffSt) {
  const TriangleMesh m = load_triangle_mesh(kUv / "quad_st.off");
  EXPECT_EQ(m.uvs, (std::vector<glm::dvec2>{{0.25, 0.5}, {0.75, 0.5}, {0.75, 1.0}, {0.25, 1.0}}));
}

TEST(MeshUvs, OmTexcoords) {
  test::TempDir dir;
  PolyMesh mesh = meshgen::icosphere(1.0, 0);
  for (auto vh : mesh.vertices()) mesh.set_texcoord2D(vh, {vh.idx() / 16.0, 1.0 - vh.idx() / 32.0});
  write_mesh(dir / "m.om", mesh, Options::VertexTexCoord | Options::VertexNormal);
  const TriangleMesh m = load_triangle_mesh(dir / "m.om");
  ASSERT_EQ(m.uvs.size(), mesh.n_vertices());
  for (std::size_t i = 0; i < m.uvs.size(); ++i) {
    const double k = static_cast<double>(i);
    EXPECT_EQ(m.uvs[i], glm::dvec2(k / 16.0, 1.0 - k / 32.0)) << i;
  }
}

TEST(MeshUvs, PlyRoundTripKeepsUvsInTheirType) {
  test::TempDir dir;
  for (const char* name : {"quad_uv.ply", "quad_st.ply"}) {
    const LoadedMesh in = read_mesh(kUv / name);
    for (const Options& extra : {Options(), Options(Options::Binary)}) {
      Options options = in.read_options;
      options += extra;
      write_mesh(dir / "out.ply", in.mesh, options, in.extra_vertex_properties);
      const std::string text = test::read_file(dir / "out.ply");
      // quad_uv's are floats, quad_st's are not: each keeps the type that holds it exactly.
      const bool floats = std::string(name) == "quad_uv.ply";
      EXPECT_NE(text.find(floats ? "property float u\nproperty float v\n"
                                 : "property double u\nproperty double v\n"),
                std::string::npos)
          << name;
      EXPECT_EQ(load_triangle_mesh(dir / "out.ply").uvs, to_triangle_mesh(in).uvs) << name;
    }
  }
}

void expect_input_error(const fs::path& path, const std::string& where, const std::string& what) {
  try {
    read_mesh(path);
    FAIL() << path << " was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.where(), where) << e.what();
    EXPECT_NE(e.what_only().find(what), std::string::npos) << e.what();
  }
}

TEST(MeshUvs, BadUvsNameFileAndLine) {
  expect_input_error(kUv / "nan_uv.ply", "13", "vertex 1 has a non-finite texture coordinate");
  expect_input_error(kUv / "nan_vt.obj", "5", "texture coordinate 1 is not a finite number");
  expect_input_error(kUv / "vt_out_of_range.obj", "6",
                     "face texture coordinate index 3 is out of range (the file has 2 texture "
                     "coordinates)");
  expect_input_error(kUv / "inf_st.off", "5", "vertex 2 has a non-finite texture coordinate");
}

// Faces that mix corners with and without vt: read, as assimp and tinyobjloader read them,
// without UVs (OpenMesh leaves the corners without vt undefined), and the warning names
// the first face line that breaks ranks.
void expect_read_without_uvs(const fs::path& path, std::size_t faces, const std::string& line) {
  const LoadedMesh loaded = read_mesh(path);
  EXPECT_FALSE(loaded.read_options.vertex_has_texcoord());
  EXPECT_EQ(loaded.mesh.n_faces(), faces);
  const std::string expected =
      "its faces mix corners with and without texture coordinates (vt), first at line " + line +
      ": the mesh is read without UVs";
  EXPECT_EQ(std::count(loaded.warnings.begin(), loaded.warnings.end(), expected), 1)
      << ::testing::PrintToString(loaded.warnings);
  const TriangleMesh m = to_triangle_mesh(loaded);
  EXPECT_TRUE(m.uvs.empty());
}

TEST(MeshUvs, FacesMixingCornersWithAndWithoutVtAreReadWithoutUvs) {
  expect_read_without_uvs(kUv / "mixed_vt.obj", 2, "9");
}

TEST(MeshUvs, DebianAssimpRegressionObjMixingVtIsReadWithoutUvs) {
  // assimp-testmodels' regr01.obj: 2,042 faces without vt, then 668 with (first at line 2661).
  const fs::path regr01 = "/usr/share/assimp/models/OBJ/regr01.obj";
  if (!fs::exists(regr01)) GTEST_SKIP() << regr01 << " is absent (assimp-testmodels)";
  expect_read_without_uvs(regr01, 2710, "2661");
}

// Through the binary: a render says what the reader dropped; a material that needs the UVs
// then fails with one error line that says why the mesh has none.
TEST(MeshUvs, ARenderWarnsThatMixedVtDroppedTheUvsAndAMapMaterialsErrorSaysWhy) {
  test::TempDir dir;
  const std::string mesh = (kUv / "mixed_vt.obj").string();
  auto scene = [&](const std::string& thickness) {
    const fs::path p = dir.path() / ("s" + std::to_string(thickness.size()) + ".json");
    test::write_file(p, R"({ "image": { "width": 16, "height": 12 },
  "camera": { "eye": [0.5, 0.5, 3], "target": [0.5, 0.5, 0] },
  "materials": { "m": { "albedo": [0.8, 0.8, 0.8],
                        "translucency": { "power": 4, "thickness": )" +
                            thickness + R"( } } },
  "lights": [ { "type": "directional", "direction": [0, 0, -1], "color": [1, 1, 1] } ],
  "objects": [ { "mesh": ")" +
                            mesh + R"(", "material": "m" } ] })");
    return p.string();
  };
  const std::string why =
      "its faces mix corners with and without texture coordinates (vt), first at line 9";
  const std::string warning =
      "ltrender: warning: " + mesh + ": " + why + ": the mesh is read without UVs\n";
  const auto drawn = test::run_ltrender("render " + scene("0.5") + " --path reference -o " +
                                        (dir.path() / "a.png").string());
  EXPECT_EQ(drawn.exit_code, 0) << drawn.err;
  EXPECT_NE(drawn.err.find(warning), std::string::npos) << drawn.err;
  EXPECT_TRUE(fs::exists(dir.path() / "a.png"));

  const std::string map =
      (lt::build_paths::source_dir() / "meshes" / "teapot_thickness.png").string();
  const std::string scene_file = scene(R"({ "texture": ")" + map + R"(" })");
  const auto refused = test::run_ltrender("render " + scene_file + " --path reference -o " +
                                          (dir.path() / "b.png").string());
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  // One error line, which says why the mesh has no UVs (warnings are printed once the scene is
  // loaded, so the error does not follow them).
  EXPECT_EQ(refused.err, "ltrender: error: " + scene_file +
                             ":objects[0].mesh: material \"m\" "
                             "samples the thickness map " +
                             map + " but " + mesh + " has no texture coordinates (UVs): " + why +
                             "\n");
  EXPECT_FALSE(fs::exists(dir.path() / "b.png"));
}

}  // namespace
}  // namespace lt
