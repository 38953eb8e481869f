// Mesh I/O and the procedural meshes: every malformed input is one InputError naming the file,
// round trips keep what they promise, generated meshes are closed, outward and measure what
// geometry says they should.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "core/build_paths.h"
#include "core/error.h"
#include "core/fs.h"
#include "mesh/mesh_io.h"
#include "mesh/meshgen.h"
#include "mesh/normals.h"
#include "test_util.h"

namespace lt {
namespace {

namespace fs = std::filesystem;
using OpenMesh::IO::Options;

const fs::path kData = lt::build_paths::source_dir() / "tests" / "data" / "meshes";

using test::TempDir;  // a scratch directory per test, removed afterwards

void write_text(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

bool has_warning(const LoadedMesh& m, const std::string& part) {
  for (const auto& w : m.warnings) {
    if (w.find(part) != std::string::npos) return true;
  }
  return false;
}

std::string all_warnings(const LoadedMesh& m) {
  std::string s;
  for (const auto& w : m.warnings) s += w + "; ";
  return s;
}

// --- geometry measures used by the generator tests -------------------------------------------

// Volume by the divergence theorem: positive when the triangles face outward.
double signed_volume(const TriangleMesh& m) {
  double v = 0.0;
  for (const auto& t : m.triangles) {
    v += glm::dot(m.positions[t.x], glm::cross(m.positions[t.y], m.positions[t.z])) / 6.0;
  }
  return v;
}

double area(const TriangleMesh& m) {
  double a = 0.0;
  for (const auto& t : m.triangles) {
    a += 0.5 * glm::length(glm::cross(m.positions[t.y] - m.positions[t.x],
                                      m.positions[t.z] - m.positions[t.x]));
  }
  return a;
}

// Closed and consistently oriented: each directed edge appears once and its reverse once.
// With `weld`, vertices at identical positions count as one (the box has separate vertices per
// face); without, indices decide (a degenerate triangle may have two corners at one position).
// Returns the number of directed edges without a partner (0 for a closed mesh).
std::size_t unmatched_edges(const TriangleMesh& m, bool weld = true) {
  std::map<std::array<double, 3>, unsigned> welded;
  std::vector<unsigned> id(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const auto& p = m.positions[i];
    id[i] = weld ? welded
                       .emplace(std::array<double, 3>{p.x, p.y, p.z},
                                static_cast<unsigned>(welded.size()))
                       .first->second
                 : static_cast<unsigned>(i);
  }
  std::map<std::pair<unsigned, unsigned>, int> directed;
  for (const auto& t : m.triangles) {
    const unsigned c[3] = {id[t.x], id[t.y], id[t.z]};
    for (int k = 0; k < 3; ++k) ++directed[{c[k], c[(k + 1) % 3]}];
  }
  std::size_t unmatched = 0;
  for (const auto& [edge, count] : directed) {
    EXPECT_EQ(count, 1) << "directed edge used twice: faces disagree on orientation";
    auto it = directed.find({edge.second, edge.first});
    if (it == directed.end() || it->second != count) ++unmatched;
  }
  return unmatched;
}

TriangleMesh triangles_of(const PolyMesh& mesh, bool colors = false) {
  LoadedMesh loaded;
  loaded.mesh = mesh;
  loaded.read_options = Options::VertexNormal;
  if (colors) loaded.read_options += Options::VertexColor;
  return to_triangle_mesh(loaded);
}

void expect_unit_normals(const TriangleMesh& m, const std::string& what) {
  for (std::size_t i = 0; i < m.normals.size(); ++i) {
    ASSERT_NEAR(glm::length(m.normals[i]), 1.0, 1e-12) << what << " vertex " << i;
  }
}

// =============================================================================================
// Bad input: one InputError naming the file, never a crash.

struct BadMeshCase {
  const char* file;  // under tests/data/meshes/bad
  const char* what;  // part of the message
  const char* line;  // expected InputError::where(), "" when the reader cannot know a line
};

std::ostream& operator<<(std::ostream& o, const BadMeshCase& c) {
  return o << c.file;
}

class BadMesh : public ::testing::TestWithParam<BadMeshCase> {};

TEST_P(BadMesh, IsOneInputErrorNamingTheFile) {
  const BadMeshCase& c = GetParam();
  const fs::path path = kData / "bad" / c.file;
  ASSERT_TRUE(fs::exists(path)) << path;
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  try {
    read_mesh(path);
    ::testing::internal::GetCapturedStdout();
    ::testing::internal::GetCapturedStderr();
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string out = ::testing::internal::GetCapturedStdout();
    const std::string err = ::testing::internal::GetCapturedStderr();
    EXPECT_EQ(e.file(), path.string());
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    // In a sanitized build OpenMesh's OM reader may overflow inside the child before it returns
    // the broken mesh the release build reports: that is the crash message (read_om_in_child).
    const bool sanitizer_crash =
        test::kSanitizedBuild && path.extension() == ".om" &&
        e.what_only().find("OpenMesh's OM reader crashed on this file (sanitizer report") !=
            std::string::npos;
    if (!sanitizer_crash) {
      EXPECT_NE(e.what_only().find(c.what), std::string::npos) << "message: " << e.what();
    }
    EXPECT_EQ(e.where(), c.line) << e.what();
    // OpenMesh's own chatter stays out of the terminal: the user sees our one line only.
    EXPECT_EQ(out, "");
    EXPECT_EQ(err, "");
  }
}

INSTANTIATE_TEST_SUITE_P(
    Ply, BadMesh,
    ::testing::Values(
        BadMeshCase{"empty.ply", "file is empty", ""},
        BadMeshCase{"not_ply.ply", "not a PLY file", "1"},
        BadMeshCase{"header_only.ply", "declares 3 vertex elements but the file is too short", ""},
        // OpenMesh 9.0 loops forever on this one.
        BadMeshCase{"header_truncated.ply", "no end_header", ""},
        BadMeshCase{"nan_ascii.ply", "vertex 1 has a non-finite coordinate (nan", "11"},
        BadMeshCase{"inf_ascii.ply", "vertex 2 has a non-finite coordinate (0, -inf", "12"},
        BadMeshCase{"nan_binary.ply", "vertex 2 has a non-finite coordinate", ""},
        BadMeshCase{"bad_token.ply",
                    "'x' in vertex 1 is not a number of the declared type (property z)", "11"},
        BadMeshCase{"list_in_vertex.ply",
                    "'1.5' in vertex 0 is not a number of the declared type (property list "
                    "vertex_indices)",
                    "10"},
        BadMeshCase{"out_of_range_ascii.ply",
                    "face 0: vertex index 7 is out of range (the file has 3 vertices)", "13"},
        BadMeshCase{"out_of_range_binary.ply", "vertex index 99999999 is out of range", ""},
        BadMeshCase{"negative_index.ply", "vertex index -1 is out of range", "13"},
        BadMeshCase{"two_vertex_face.ply", "face 0 has 2 vertices", "13"},
        BadMeshCase{"truncated_ascii.ply", "declares 3 vertex elements but the file is too short",
                    ""},
        BadMeshCase{"truncated_binary.ply", "file ends inside face 0 of 1", ""},
        BadMeshCase{"no_faces.ply", "3 vertices but no faces", ""},
        BadMeshCase{"zero_vertices.ply", "no vertices", ""},
        // OpenMesh would try to reserve memory for 2e9 vertices first.
        BadMeshCase{"huge_count.ply",
                    "declares 2000000000 vertex elements but the file is too short", ""},
        BadMeshCase{"ushort_color.ply", "colour property 'red' must be uchar, float or double",
                    ""}));

INSTANTIATE_TEST_SUITE_P(
    Obj, BadMesh,
    ::testing::Values(
        // OpenMesh writes through these indices unchecked when the corner also has a normal.
        BadMeshCase{"out_of_range.obj",
                    "face vertex index 9 is out of range (the file has 3 vertices)", "4"},
        BadMeshCase{"zero_index.obj", "face corner '0' has no valid vertex index", "4"},
        BadMeshCase{"negative_out_of_range.obj", "face vertex index -4 is out of range", "4"},
        // OpenMesh would silently drop the vertex and shift every later index.
        BadMeshCase{"nan.obj", "vertex 1 has a non-finite coordinate ('nan'", "2"},
        BadMeshCase{"garbage_vertex.obj", "'x' is not a number", "2"},
        BadMeshCase{"no_faces.obj", "3 vertices but no faces", ""},
        BadMeshCase{"empty.obj", "no vertices", ""},
        BadMeshCase{"normal_out_of_range.obj",
                    "face normal index 5 is out of range (the file has 1 normal)", "5"},
        BadMeshCase{"corner_without_vertex.obj", "face corner '//1' has no valid vertex index",
                    "5"},
        BadMeshCase{"two_vertex_face.obj", "a face needs at least 3 vertices", "4"},
        // As assimp-testmodels' OBJ/box_UTF16BE.obj: read as bytes it has no vertex.
        BadMeshCase{"utf16.obj", "UTF-16 text (it starts with a byte-order mark)", "1"}));

INSTANTIATE_TEST_SUITE_P(
    Off, BadMesh,
    ::testing::Values(
        BadMeshCase{"out_of_range.off",
                    "face 0: vertex index 9 is out of range (the file has 3 vertices)", "6"},
        BadMeshCase{"negative.off", "vertex index -1 is out of range", "6"},
        BadMeshCase{"truncated.off", "file ends after 2 of 3 vertices", ""},
        BadMeshCase{"huge_count.off", "counts (3000000000 vertices", "2"},
        BadMeshCase{"nan.off", "vertex 1 has a non-finite coordinate", "4"},
        BadMeshCase{"face_too_long.off", "face 0 lists fewer than 300 vertices", "6"}));

INSTANTIATE_TEST_SUITE_P(
    Stl, BadMesh,
    ::testing::Values(
        BadMeshCase{"truncated_binary.stl",
                    "declares 1000 triangles, which need 50084 bytes; the file has 234", ""},
        BadMeshCase{"nan_binary.stl", "triangle 0 has a non-finite vertex coordinate", ""},
        BadMeshCase{"nan_ascii.stl", "'nan' is not a finite number", "5"},
        BadMeshCase{"empty.stl", "file is empty", ""}));

INSTANTIATE_TEST_SUITE_P(
    Other, BadMesh,
    ::testing::Values(
        BadMeshCase{"mesh.xyz", "unknown mesh format '.xyz'", ""},
        // These three kill a process that reads them with OpenMesh (SIGSEGV, abort from a double
        // free, gigabytes allocated within seconds): the OM reader runs in a child process.
        BadMeshCase{"corrupt_segv.om", "face 1 has a broken halfedge loop", ""},
        BadMeshCase{"corrupt_abort.om", "face 2 has a broken halfedge loop", ""},
        BadMeshCase{"corrupt_runaway.om", "OpenMesh could not read it: std::bad_alloc", ""},
        BadMeshCase{"truncated.om", "OpenMesh could not read it", ""},
        // OpenMesh's last log line is the reason; it was read from a destroyed string (freed
        // bytes in the message, use-after-free under ASan).
        BadMeshCase{"unknown_chunk.om", "OpenMesh could not read it: Unknown chunk type ignored!",
                    ""}));

TEST(ReadMesh, MissingFileAndDirectory) {
  const fs::path missing = kData / "bad" / "does_not_exist.ply";
  try {
    read_mesh(missing);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing.string());
    EXPECT_EQ(e.what_only(), "file not found");
  }
  try {
    read_mesh(kData / "bad");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.what_only(), "is a directory, not a mesh file");
  }
}

// What Geomview's OFF allows and OpenMesh's reader misreads (it would refuse the comment, lose the
// counts and read the face colour as the next face) is read as the plain triangle; the face
// colour is ignored with a warning.
TEST(ReadMesh, OffCommentsCountsOnTheKeywordLineAndFaceColoursAreRead) {
  for (const char* name : {"comment.off", "counts_on_first_line.off", "face_colour.off"}) {
    const LoadedMesh m = read_mesh(kData / "odd" / name);
    const TriangleMesh t = to_triangle_mesh(m);
    EXPECT_EQ(t.positions, (std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}})) << name;
    EXPECT_EQ(t.triangles, (std::vector<glm::uvec3>{{0, 1, 2}})) << name;
    const bool colour = std::string(name) == "face_colour.off";
    EXPECT_EQ(has_warning(m, "1 face colour ignored (the paths shade with vertex colours only)"),
              colour)
        << name << ": " << all_warnings(m);
  }
}

// =============================================================================================
// Colours: 8-bit values come out as v / 255, float values exactly.

TEST(ReadMesh, EightBitColoursAreOver255) {
  for (const char* name : {"colors8.ply", "colors.off", "colors_spaced.off"}) {
    const LoadedMesh m = read_mesh(kData / "odd" / name);
    ASSERT_TRUE(m.read_options.vertex_has_color()) << name;
    const TriangleMesh t = to_triangle_mesh(m);
    ASSERT_EQ(t.colors.size(), 3u);
    EXPECT_EQ(t.colors[0], glm::dvec3(1.0f, 128.0f / 255.0f, 0.0f)) << name;
    EXPECT_EQ(t.colors[1], glm::dvec3(10.0f / 255.0f, 20.0f / 255.0f, 30.0f / 255.0f)) << name;
    EXPECT_EQ(t.colors[2], glm::dvec3(1.0f / 255.0f, 2.0f / 255.0f, 3.0f / 255.0f)) << name;
  }
}

TEST(ReadMesh, FloatColoursAreExact) {
  // OpenMesh's PLY reader would return 0.5 as 127/255 and 0.123 as 31/255.
  for (const char* name : {"colors_float.ply", "colors_float.off", "colors.obj"}) {
    const LoadedMesh m = read_mesh(kData / "odd" / name);
    const TriangleMesh t = to_triangle_mesh(m);
    ASSERT_GE(t.colors.size(), 3u) << name;
    EXPECT_EQ(t.colors[0], glm::dvec3(0.5f, 0.123f, 1.0f)) << name;
    EXPECT_EQ(t.colors[1], glm::dvec3(0.1f, 0.2f, 0.3f)) << name;
    EXPECT_EQ(t.colors[2], glm::dvec3(0.0f, 0.0f, 0.999f)) << name;
  }
  // The OBJ's fourth vertex is in no face: OpenMesh leaves its colour unset; ours is the file's.
  const TriangleMesh obj = load_triangle_mesh(kData / "odd" / "colors.obj");
  EXPECT_EQ(obj.colors[3], glm::dvec3(0.25f));
}

TEST(ReadMesh, NoColoursWhenTheFileHasNone) {
  const TriangleMesh t = load_triangle_mesh(kData / "odd" / "quads.obj");
  EXPECT_FALSE(t.has_colors());
}

// =============================================================================================
// Normals

TEST(ReadMesh, MissingNormalsAreComputedOutward) {
  // quads.obj: the corner of a box, a 2 x 2 square at z = 0 facing +z and a 2 x 1 one at
  // y = -1 facing -y.
  const LoadedMesh m = read_mesh(kData / "odd" / "quads.obj");
  EXPECT_EQ(m.notes, std::vector<std::string>{
                         "no vertex normals in the file: computed from the faces (area-weighted)"});
  EXPECT_FALSE(has_warning(m, "no vertex normals in the file")) << all_warnings(m);
  const TriangleMesh t = to_triangle_mesh(m);
  EXPECT_NEAR(t.normals[2].z, 1.0, 1e-12);  // only in the first quad
  EXPECT_NEAR(t.normals[3].z, 1.0, 1e-12);
  EXPECT_NEAR(t.normals[4].y, -1.0, 1e-12);  // only in the second
  // Vertices 0 and 1 are shared: weighted by area, 4 * (0, 0, 1) + 2 * (0, -1, 0).
  EXPECT_NEAR(t.normals[0].z, 2.0 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(t.normals[0].y, -1.0 / std::sqrt(5.0), 1e-12);
}

TEST(ReadMesh, BadFileNormalsAreRepaired) {
  // Quad at z = 0 facing +z: normals nan, zero, (0,0,5) and (0,0,1). The text "nan" would put
  // OpenMesh's stream into a failed state and lose the face.
  const LoadedMesh m = read_mesh(kData / "odd" / "bad_normals.ply");
  EXPECT_TRUE(has_warning(m, "1 non-finite normal recomputed")) << all_warnings(m);
  EXPECT_TRUE(has_warning(m, "1 zero-length normal recomputed")) << all_warnings(m);
  EXPECT_TRUE(has_warning(m, "1 non-unit normal normalised")) << all_warnings(m);
  const TriangleMesh t = to_triangle_mesh(m);
  ASSERT_EQ(t.triangles.size(), 2u);
  for (const auto& n : t.normals) EXPECT_EQ(n, glm::dvec3(0, 0, 1));
}

TEST(ReadMesh, IsolatedVertexKeepsAZeroNormal) {
  const LoadedMesh m = read_mesh(kData / "odd" / "isolated_vertex.ply");
  EXPECT_TRUE(has_warning(m, "1 vertex has no normal")) << all_warnings(m);
  const TriangleMesh t = to_triangle_mesh(m);
  EXPECT_EQ(t.normals[3], glm::dvec3(0.0));
  EXPECT_EQ(t.normals[0], glm::dvec3(0, 0, 1));
}

TEST(ReadMesh, ObjCornersWithoutNormalsGetComputedOnes) {
  // Vertex 4 (index 3) is only in a face without normals; vertex 5 is in no face at all.
  const LoadedMesh m = read_mesh(kData / "odd" / "partial_normals.obj");
  EXPECT_TRUE(m.read_options.vertex_has_normal());
  EXPECT_TRUE(has_warning(m, "2 vertices without a normal in the file")) << all_warnings(m);
  const TriangleMesh t = to_triangle_mesh(m);
  EXPECT_EQ(t.normals[0], glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.normals[3], glm::dvec3(0, 0, 1));
  EXPECT_EQ(t.normals[4], glm::dvec3(0.0));
}

// =============================================================================================
// Odd but valid files

TEST(ReadMesh, FacesThatRepeatAVertexAreDroppedWithAWarning) {
  const LoadedMesh m = read_mesh(kData / "odd" / "repeated_vertex.ply");
  EXPECT_EQ(m.mesh.n_faces(), 1u);
  EXPECT_TRUE(has_warning(m, "1 face naming a vertex twice dropped")) << all_warnings(m);
}

TEST(ReadMesh, NonManifoldFacesAreSplitOffKeepingTheirAttributes) {
  for (const char* name : {"nonmanifold.ply", "nonmanifold.obj"}) {
    const LoadedMesh m = read_mesh(kData / "odd" / name);
    // The third face on edge 0-1 gets its own copies of its three vertices.
    EXPECT_EQ(m.mesh.n_faces(), 3u) << name;
    EXPECT_EQ(m.mesh.n_vertices(), 8u) << name;
    EXPECT_TRUE(has_warning(m, "3 vertices duplicated")) << name << ": " << all_warnings(m);
    const TriangleMesh t = to_triangle_mesh(m);
    ASSERT_TRUE(t.has_colors()) << name;
    // Each copy has the position, colour and normal of the vertex it copies.
    for (std::size_t v = 5; v < 8; ++v) {
      std::size_t original = 0;
      while (original < 5 && t.positions[original] != t.positions[v]) ++original;
      ASSERT_LT(original, 5u) << name;
      EXPECT_EQ(t.colors[v], t.colors[original]) << name;
      EXPECT_EQ(t.normals[v], glm::dvec3(0, 0, 1)) << name;
    }
  }
}

TEST(ReadMesh, BigEndianCrLfDoublePly) {
  const LoadedMesh m = read_mesh(kData / "odd" / "big_endian_crlf.ply");
  EXPECT_TRUE(m.read_options.is_binary());
  const TriangleMesh t = to_triangle_mesh(m);
  ASSERT_EQ(t.positions.size(), 3u);
  EXPECT_EQ(t.positions[0], glm::dvec3(1e6 + 0.125, 0, 0));  // double survives
  EXPECT_EQ(t.positions[1], glm::dvec3(1e6 + 1, 0, 0));
}

TEST(ReadMesh, ListPropertiesAndExtraElementsAreSkipped) {
  // OpenMesh 9.0 skips a list property by a single value and would misread the rest.
  const TriangleMesh t = load_triangle_mesh(kData / "odd" / "extra_elements.ply");
  ASSERT_EQ(t.positions.size(), 3u);
  EXPECT_EQ(t.positions[2], glm::dvec3(0, 1, 0));
  ASSERT_EQ(t.triangles.size(), 1u);
  EXPECT_EQ(t.triangles[0], glm::uvec3(0, 1, 2));
}

// 821 bytes of 25 such header lines kept bake busy for ~59 s: records of no properties hold no
// bytes, so they cost nothing to skip.
TEST(ReadMesh, ElementsWithoutPropertiesCostNothing) {
  TempDir dir;
  std::string ply = "ply\nformat ascii 1.0\n";
  for (int i = 0; i < 3; ++i) ply += "element junk" + std::to_string(i) + " 2147483647\n";
  ply +=
      "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  write_text(dir.path() / "junk.ply", ply);
  const auto start = std::chrono::steady_clock::now();
  const LoadedMesh m = read_mesh(dir.path() / "junk.ply");
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 1.0);  // ~7 s when each empty record was a loop iteration
  EXPECT_EQ(m.mesh.n_vertices(), 4u);
  EXPECT_EQ(m.mesh.n_faces(), 4u);
}

// Several unknown lines: one warning naming the first, whose non-printable bytes and length
// cannot break the warning's single line.
TEST(ReadMesh, UnknownPlyHeaderLinesAreOneWarning) {
  TempDir dir;
  write_text(dir.path() / "t.ply", "ply\nformat ascii 1.0\nmade\tby \x01tool " +
                                       std::string(100, 'v') +
                                       "\nelement vertex 3\nproperty float x\nproperty float y\n"
                                       "property float z\nexporter 2\nelement face 1\n"
                                       "property list uchar int vertex_indices\nend_header\n"
                                       "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const LoadedMesh m = read_mesh(dir.path() / "t.ply");
  EXPECT_EQ(m.mesh.n_faces(), 1u);
  EXPECT_EQ(m.warnings.front(),
            "2 header lines are not PLY keywords (the first: line 3 'made?by ?tool " +
                std::string(66, 'v') + "...'): read as comments");
}

TEST(ReadMesh, PolygonsAreFannedKeepingTheirWinding) {
  const TriangleMesh t = load_triangle_mesh(kData / "odd" / "quads.obj");
  ASSERT_EQ(t.triangles.size(), 4u);
  for (const auto& tri : t.triangles) {
    const glm::dvec3 n = glm::cross(t.positions[tri.y] - t.positions[tri.x],
                                    t.positions[tri.z] - t.positions[tri.x]);
    EXPECT_GT(glm::dot(n, t.normals[tri.x] + t.normals[tri.y] + t.normals[tri.z]), 0.0);
  }
  EXPECT_NEAR(area(t), 6.0, 1e-12);
}

TEST(ReadMesh, MissingMaterialLibraryIsNotPrinted) {
  TempDir dir;
  write_text(dir / "m.obj", "mtllib nowhere.mtl\nusemtl x\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ::testing::internal::CaptureStderr();
  ::testing::internal::CaptureStdout();
  const LoadedMesh m = read_mesh(dir / "m.obj");
  EXPECT_EQ(::testing::internal::GetCapturedStdout(), "");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
  EXPECT_EQ(m.mesh.n_faces(), 1u);
}

// =============================================================================================
// Round trips

PolyMesh colored_sphere() {
  PolyMesh mesh = meshgen::icosphere(1.0, 2);
  int i = 0;
  for (auto vh : mesh.vertices()) {
    // Values that 8 bits cannot hold, and one outside [0, 1] (a baker may write those).
    mesh.set_color(
        vh, PolyMesh::Color(0.123f * static_cast<float>(i % 7), 0.5f, i == 5 ? 1.5f : 0.001f));
    ++i;
  }
  return mesh;
}

TEST(RoundTrip, BinaryPlyKeepsFloatColoursNormalsAndDoublePositions) {
  TempDir dir;
  PolyMesh mesh = colored_sphere();
  meshgen::translate(mesh, glm::dvec3(1e6 + 0.3, -2e6, 1e-3));
  write_mesh(dir / "s.ply", mesh,
             Options::Binary | Options::VertexNormal | Options::VertexColor | Options::ColorFloat);
  const LoadedMesh back = read_mesh(dir / "s.ply");
  EXPECT_TRUE(back.read_options.is_binary());
  EXPECT_TRUE(back.read_options.vertex_has_normal());
  EXPECT_TRUE(back.read_options.vertex_has_color());
  EXPECT_TRUE(back.read_options.color_is_float());
  EXPECT_TRUE(back.warnings.empty()) << all_warnings(back);
  ASSERT_EQ(back.mesh.n_vertices(), mesh.n_vertices());
  ASSERT_EQ(back.mesh.n_faces(), mesh.n_faces());
  for (auto vh : mesh.vertices()) {
    EXPECT_EQ(back.mesh.point(vh), mesh.point(vh));
    EXPECT_EQ(back.mesh.color(vh), mesh.color(vh));
    EXPECT_NEAR((back.mesh.normal(vh) - mesh.normal(vh)).norm(), 0.0, 1e-7);  // float normals
  }
  for (auto fh : mesh.faces()) {
    auto a = mesh.fv_range(fh).to_vector(), b = back.mesh.fv_range(fh).to_vector();
    EXPECT_EQ(a, b);
  }
}

TEST(RoundTrip, AsciiPlyIsExactToo) {
  TempDir dir;
  PolyMesh mesh = colored_sphere();
  meshgen::translate(mesh, glm::dvec3(0.1, 1e6, -1e-7));
  write_mesh(dir / "s.ply", mesh,
             Options::VertexNormal | Options::VertexColor | Options::ColorFloat);
  EXPECT_EQ(test::read_file(dir / "s.ply").substr(0, 21), "ply\nformat ascii 1.0\n");
  const LoadedMesh back = read_mesh(dir / "s.ply");
  for (auto vh : mesh.vertices()) {
    EXPECT_EQ(back.mesh.point(vh), mesh.point(vh));
    EXPECT_EQ(back.mesh.color(vh), mesh.color(vh));
  }
}

TEST(RoundTrip, EightBitColoursRoundToNearest) {
  TempDir dir;
  PolyMesh mesh = colored_sphere();
  write_mesh(dir / "s.ply", mesh, Options::Binary | Options::VertexColor);
  const LoadedMesh back = read_mesh(dir / "s.ply");
  EXPECT_FALSE(back.read_options.color_is_float());
  for (auto vh : mesh.vertices()) {
    for (int k = 0; k < 3; ++k) {
      const float c = std::clamp(mesh.color(vh)[k], 0.0f, 1.0f);
      EXPECT_EQ(back.mesh.color(vh)[k], std::round(c * 255.0f) / 255.0f);
    }
  }
}

TEST(RoundTrip, OurPlyIsReadableByOpenMeshItself) {
  TempDir dir;
  const PolyMesh mesh = colored_sphere();
  write_mesh(dir / "s.ply", mesh,
             Options::Binary | Options::VertexNormal | Options::VertexColor | Options::ColorFloat);
  PolyMesh om;
  Options opts = Options::VertexNormal | Options::VertexColor;
  ASSERT_TRUE(OpenMesh::IO::read_mesh(om, (dir / "s.ply").string(), opts));
  EXPECT_EQ(om.n_vertices(), mesh.n_vertices());
  EXPECT_EQ(om.n_faces(), mesh.n_faces());
  EXPECT_TRUE(opts.vertex_has_normal() && opts.vertex_has_color());
  for (auto vh : mesh.vertices()) EXPECT_NEAR((om.point(vh) - mesh.point(vh)).norm(), 0.0, 1e-6);
}

TEST(RoundTrip, OtherFormatsThroughOpenMesh) {
  TempDir dir;
  const PolyMesh mesh = meshgen::torus(0.7, 0.3, 24, 12);
  for (const char* name : {"t.obj", "t.off", "t.om", "t.stl"}) {
    const bool stl = std::string(name) == "t.stl";
    write_mesh(dir / name, mesh, stl ? Options(Options::Binary) : Options(Options::VertexNormal));
    const LoadedMesh back = read_mesh(dir / name);
    EXPECT_EQ(back.mesh.n_faces(), mesh.n_faces()) << name;
    if (stl) continue;  // STL has no shared vertices in the file; OpenMesh welds them again
    ASSERT_EQ(back.mesh.n_vertices(), mesh.n_vertices()) << name;
    // OBJ and OFF are read as float by OpenMesh; OM keeps double.
    const double tolerance = std::string(name) == "t.om" ? 0.0 : 1e-7;
    for (auto vh : mesh.vertices()) {
      EXPECT_LE((back.mesh.point(vh) - mesh.point(vh)).norm(), tolerance) << name;
      EXPECT_NEAR((back.mesh.normal(vh) - mesh.normal(vh)).norm(), 0.0, 1e-6) << name;
    }
  }
}

TEST(WriteMesh, ErrorsNameTheFileAndLeaveNothingBehind) {
  TempDir dir;
  const PolyMesh mesh = meshgen::quad(1.0, 1);
  try {
    write_mesh(dir / "missing_dir" / "q.ply", mesh, Options::Binary);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / "missing_dir" / "q.ply").string());
  }
  try {
    write_mesh(dir / "q.xyz", mesh, Options::Binary);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("unknown mesh format '.xyz'"), std::string::npos);
  }
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

// =============================================================================================
// Generators

TEST(Meshgen, IcosphereCountsClosedOutwardUnit) {
  for (int s = 0; s <= 5; ++s) {
    const TriangleMesh t = triangles_of(meshgen::icosphere(2.0, s));
    const std::size_t four_s = std::size_t{1} << (2 * s);
    EXPECT_EQ(t.positions.size(), 10 * four_s + 2);
    EXPECT_EQ(t.triangles.size(), 20 * four_s);
    EXPECT_EQ(unmatched_edges(t), 0u) << s;
    const double sphere = 4.0 / 3.0 * std::numbers::pi * 8.0;
    // Inscribed polyhedron: a little less than the sphere, converging with subdivision.
    EXPECT_GT(signed_volume(t), 0.0);
    EXPECT_LT(signed_volume(t), sphere);
    if (s >= 4) EXPECT_NEAR(signed_volume(t) / sphere, 1.0, 0.005) << s;
    expect_unit_normals(t, "icosphere");
    for (std::size_t i = 0; i < t.positions.size(); ++i) {
      EXPECT_NEAR(glm::length(t.positions[i]), 2.0, 1e-12);
      EXPECT_NEAR(glm::dot(t.normals[i], t.positions[i] / 2.0), 1.0, 1e-12);
    }
  }
}

TEST(Meshgen, BoxIsClosedWithFlatFaces) {
  const glm::dvec3 h(0.5, 1.0, 0.75);
  const TriangleMesh t = triangles_of(meshgen::box(h, 8));
  EXPECT_EQ(t.triangles.size(), 6u * 8 * 8 * 2);
  EXPECT_EQ(unmatched_edges(t), 0u);
  EXPECT_NEAR(signed_volume(t), 8 * h.x * h.y * h.z, 1e-12);
  expect_unit_normals(t, "box");
  for (const auto& tri : t.triangles) {
    // Crisp edges: all three corners carry the face's own normal.
    const glm::dvec3 n = glm::normalize(glm::cross(t.positions[tri.y] - t.positions[tri.x],
                                                   t.positions[tri.z] - t.positions[tri.x]));
    for (unsigned v : {tri.x, tri.y, tri.z}) EXPECT_NEAR(glm::length(t.normals[v] - n), 0.0, 1e-12);
  }
}

TEST(Meshgen, TorusIsClosedOutwardWithTheRightVolume) {
  const double R = 0.7, r = 0.3;
  const TriangleMesh t = triangles_of(meshgen::torus(R, r, 96, 48));
  EXPECT_EQ(unmatched_edges(t), 0u);
  EXPECT_NEAR(signed_volume(t) / (2 * std::numbers::pi * std::numbers::pi * R * r * r), 1.0, 0.005);
  expect_unit_normals(t, "torus");
  for (std::size_t i = 0; i < t.positions.size(); ++i) {
    // Outward: away from the tube's centre line.
    const glm::dvec3 p = t.positions[i];
    const glm::dvec3 centre = R * glm::normalize(glm::dvec3(p.x, 0, p.z));
    EXPECT_NEAR(glm::dot(t.normals[i], (p - centre) / r), 1.0, 1e-12);
  }
}

TEST(Meshgen, QuadIsOpenAndFacesPlusZ) {
  const TriangleMesh t = triangles_of(meshgen::quad(1.0, 4));
  EXPECT_EQ(t.positions.size(), 25u);
  EXPECT_EQ(t.triangles.size(), 32u);
  EXPECT_NEAR(area(t), 4.0, 1e-12);
  EXPECT_EQ(unmatched_edges(t), 16u);  // the boundary: 4 sides of 4 cells
  for (const auto& tri : t.triangles) {
    EXPECT_GT(
        glm::cross(t.positions[tri.y] - t.positions[tri.x], t.positions[tri.z] - t.positions[tri.x])
            .z,
        0.0);
  }
  for (const auto& n : t.normals) EXPECT_EQ(n, glm::dvec3(0, 0, 1));
}

// Distance along the inward normal to the other side, by brute force (tests only).
double thickness_at(const TriangleMesh& t, std::size_t v) {
  const glm::dvec3 o = t.positions[v], d = -t.normals[v];
  double best = std::numeric_limits<double>::infinity();
  for (const auto& tri : t.triangles) {
    if (tri.x == v || tri.y == v || tri.z == v) continue;
    const glm::dvec3 a = t.positions[tri.x], e1 = t.positions[tri.y] - a,
                     e2 = t.positions[tri.z] - a;
    const glm::dvec3 p = glm::cross(d, e2);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-15) continue;
    const glm::dvec3 s = o - a;
    const double u = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double w = glm::dot(d, q) / det;
    const double dist = glm::dot(e2, q) / det;
    if (u >= 0 && w >= 0 && u + w <= 1 && dist > 1e-9) best = std::min(best, dist);
  }
  return best;
}

TEST(Meshgen, BlobIsClosedOutwardAndItsThicknessVaries) {
  const TriangleMesh t = triangles_of(meshgen::blob(5));
  EXPECT_EQ(t.positions.size(), 10242u);
  EXPECT_EQ(unmatched_edges(t), 0u);
  EXPECT_GT(signed_volume(t), 1.5);
  expect_unit_normals(t, "blob");
  // Sample the surface: the ears must be much thinner than the body.
  double thinnest = 1e9, thickest = 0;
  for (std::size_t v = 0; v < t.positions.size(); v += 97) {
    const double th = thickness_at(t, v);
    ASSERT_TRUE(std::isfinite(th)) << "vertex " << v << ": inward ray leaves the closed mesh";
    thinnest = std::min(thinnest, th);
    thickest = std::max(thickest, th);
  }
  EXPECT_LT(thinnest, 0.15);
  EXPECT_GT(thickest, 1.4);
}

TEST(Meshgen, HardCases) {
  {
    const PolyMesh mesh = meshgen::degenerate_sphere(3, 24);
    const TriangleMesh t = triangles_of(mesh);
    EXPECT_EQ(unmatched_edges(t, /*weld=*/false), 0u);  // still closed and oriented
    std::size_t zero_area = 0;
    for (const auto& tri : t.triangles) {
      const double a = glm::length(glm::cross(t.positions[tri.y] - t.positions[tri.x],
                                              t.positions[tri.z] - t.positions[tri.x]));
      if (a < 1e-15) ++zero_area;
    }
    EXPECT_EQ(zero_area, 12u + 2u * 12u);  // collinear: one each; coincident: two each
    expect_unit_normals(t, "degenerate");
  }
  {
    const TriangleMesh t = triangles_of(meshgen::zero_normal_sphere(3));
    std::size_t zero = 0;
    for (const auto& n : t.normals) zero += n == glm::dvec3(0.0);
    EXPECT_EQ(zero, (642u - 3 + 6) / 7);
  }
  {
    const TriangleMesh t = triangles_of(meshgen::nonunit_normal_sphere(3));
    EXPECT_NEAR(glm::length(t.normals[1]), 2.0, 1e-12);
    EXPECT_NEAR(glm::length(t.normals[3]), 1e-3, 1e-15);
  }
}

TEST(Meshgen, ComputedNormalsSurviveTinyAndFarMeshes) {
  for (const glm::dvec3 offset : {glm::dvec3(0.0), glm::dvec3(1e6)}) {
    for (const double radius : {1e-6, 1.0}) {
      PolyMesh mesh = meshgen::icosphere(radius, 3);
      meshgen::translate(mesh, offset);
      EXPECT_EQ(compute_normals(mesh), 0u);
      for (auto vh : mesh.vertices()) {
        const auto n = mesh.normal(vh);
        const auto dir = (mesh.point(vh) - PolyMesh::Point(offset.x, offset.y, offset.z)) / radius;
        ASSERT_NEAR(n.norm(), 1.0, 1e-12);
        ASSERT_GT(OpenMesh::dot(n, dir), 0.99) << "radius " << radius << " offset " << offset.x;
      }
    }
  }
}

// The hard-case files load as model.md wants them: no error, every normal unit or zero.
TEST(Meshgen, HardCaseFilesLoad) {
  TempDir dir;
  const auto opts = Options::Binary | Options::VertexNormal;
  for (auto& named : meshgen::standard_set()) {
    if (named.path.rfind("hard/", 0) != 0) continue;
    const fs::path path = dir / fs::path(named.path).filename().string();
    write_mesh(path, named.mesh, opts);
    const LoadedMesh m = read_mesh(path);
    EXPECT_EQ(m.mesh.n_faces(), named.mesh.n_faces()) << named.path;
    const TriangleMesh t = to_triangle_mesh(m);
    expect_unit_normals(t, named.path);
    if (named.path == "hard/zero_normals.ply") {
      EXPECT_TRUE(has_warning(m, "92 zero-length normals recomputed")) << all_warnings(m);
    } else if (named.path == "hard/nonunit_normals.ply") {
      EXPECT_TRUE(has_warning(m, "non-unit normals normalised")) << all_warnings(m);
    } else {
      EXPECT_TRUE(m.warnings.empty()) << named.path << ": " << all_warnings(m);
    }
    if (named.path == "hard/far_1e6.ply") {
      for (auto vh : m.mesh.vertices()) EXPECT_EQ(m.mesh.point(vh), named.mesh.point(vh));
    }
  }
}

// meshes/ in the repository is exactly what `ltrender meshgen meshes` writes today.
TEST(Meshgen, CommittedMeshesAreUpToDate) {
  TempDir dir;
  const fs::path committed = lt::build_paths::source_dir() / "meshes";
  for (auto& named : meshgen::standard_set()) {
    const fs::path fresh = dir / fs::path(named.path).filename().string();
    write_mesh(fresh, named.mesh, meshgen::write_options(named));
    ASSERT_TRUE(fs::exists(committed / named.path)) << named.path;
    EXPECT_TRUE(test::read_file(fresh) == test::read_file(committed / named.path))
        << named.path << " differs: run `build/ltrender meshgen meshes`";
  }
}

// =============================================================================================
// Through the command line: exit 2 and one line on stderr.

struct RunResult {
  int exit_code;
  std::string err;
};

RunResult run_ltrender(const std::string& args, const fs::path& stderr_file) {
  const std::string cmd = lt::build_paths::ltrender_binary().string() + " " + args +
                          " >/dev/null 2>" + stderr_file.string();
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, test::read_file(stderr_file)};
}

TEST(MeshgenCli, OutputThatIsAFileIsOneLineExit2) {
  TempDir dir;
  write_text(dir / "not_a_dir", "x");
  const RunResult r = run_ltrender("meshgen " + (dir / "not_a_dir").string(), dir / "err.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ltrender: error: " + (dir / "not_a_dir").string() +
                       ": exists and is not a directory\n");
}

TEST(MeshgenCli, WritesTheStandardSet) {
  TempDir dir;
  const RunResult r = run_ltrender("meshgen " + (dir / "out").string(), dir / "err.txt");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::uintmax_t total = 0;
  for (const auto& named : meshgen::standard_set()) {
    const fs::path p = dir / "out" / named.path;
    ASSERT_TRUE(fs::exists(p)) << p;
    total += fs::file_size(p);
  }
  EXPECT_LT(total, 3u << 20);  // the committed copy stays small
  const TriangleMesh sphere = load_triangle_mesh(dir / "out" / "sphere_s3.ply");
  EXPECT_EQ(sphere.positions.size(), 642u);
  // No temporaries left behind by the atomic writes.
  for (const auto& e : fs::recursive_directory_iterator(dir / "out")) {
    EXPECT_EQ(e.path().filename().string().find(kPartialOutputTag), std::string::npos) << e.path();
  }
}

// --sphere S writes one icosphere only (the bake-rate mesh of issue 3 is --sphere 7); at S = 3 it
// is the same file as the standard set's sphere_s3.ply.
TEST(MeshgenCli, SphereOptionWritesOneIcosphere) {
  TempDir dir;
  const RunResult r =
      run_ltrender("meshgen " + (dir / "out").string() + " --sphere 3", dir / "err.txt");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::read_file(dir / "out" / "sphere_s3.ply") ==
              test::read_file(lt::build_paths::source_dir() / "meshes" / "sphere_s3.ply"));
  EXPECT_FALSE(fs::exists(dir / "out" / "cube.ply"));
  EXPECT_EQ(
      run_ltrender("meshgen " + (dir / "x").string() + " --sphere 9", dir / "err.txt").exit_code,
      2);
}

}  // namespace
}  // namespace lt
