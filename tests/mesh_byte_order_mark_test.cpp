// A UTF-8 byte-order mark at the start of a text mesh (Windows editors write one) is skipped with
// a warning, in every text format: the mesh read is the one read without it. Before, OpenMesh read
// the mark into an OBJ's first line and silently lost its first vertex, shifting every index.
// A binary STL's free-form header keeps its bytes.
#include <gtest/gtest.h>

#include <string>

#include "mesh/mesh_io.h"
#include "test_util.h"

namespace lt {
namespace {

const char kBom[] = "\xEF\xBB\xBF";
const char kBomWarning[] = "a UTF-8 byte-order mark starts the file: skipped";

struct TextMesh {
  const char* name;
  const char* text;  // its first line is data, so a lost first line would show
};

void PrintTo(const TextMesh& m, std::ostream* os) {
  *os << m.name;
}

class ByteOrderMark : public ::testing::TestWithParam<TextMesh> {};

TEST_P(ByteOrderMark, IsSkippedWithAWarningAndTheMeshIsTheSame) {
  test::TempDir dir;
  const std::string name = GetParam().name;
  const fs::path plain = dir.path() / ("plain." + name), marked = dir.path() / ("marked." + name);
  test::write_file(plain, GetParam().text);
  test::write_file(marked, std::string(kBom) + GetParam().text);
  const LoadedMesh expected = read_mesh(plain);
  const LoadedMesh got = read_mesh(marked);
  ASSERT_FALSE(got.warnings.empty());
  EXPECT_EQ(got.warnings[0], kBomWarning);
  EXPECT_EQ(std::count(expected.warnings.begin(), expected.warnings.end(), kBomWarning), 0);
  const TriangleMesh a = to_triangle_mesh(expected), b = to_triangle_mesh(got);
  ASSERT_EQ(a.positions.size(), 4u);
  EXPECT_EQ(b.positions, a.positions);
  EXPECT_EQ(b.triangles, a.triangles);
  EXPECT_EQ(b.colors, a.colors);
}

INSTANTIATE_TEST_SUITE_P(
    TextFormats, ByteOrderMark,
    ::testing::Values(
        TextMesh{"obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n"},
        TextMesh{"off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
        TextMesh{"ply",
                 "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                 "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
                 "end_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"},
        TextMesh{"stl",
                 "solid quad\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
                 "vertex 1 1 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                 "vertex 1 1 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid quad\n"}),
    [](const auto& info) { return std::string(info.param.name); });

// A binary STL whose 80-byte header happens to start with the mark's bytes is read as it is.
TEST(ByteOrderMark, ABinaryStlHeaderKeepsItsBytes) {
  test::TempDir dir;
  std::string stl(80, ' ');
  stl.replace(0, 3, kBom);
  auto put_u32 = [&](std::uint32_t v) { stl.append(reinterpret_cast<const char*>(&v), 4); };
  auto put_f32 = [&](float v) { stl.append(reinterpret_cast<const char*>(&v), 4); };
  put_u32(1);
  for (float v : {0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put_f32(v);
  stl.append(2, '\0');
  const fs::path path = dir.path() / "header.stl";
  test::write_file(path, stl);
  const LoadedMesh loaded = read_mesh(path);
  EXPECT_EQ(std::count(loaded.warnings.begin(), loaded.warnings.end(), kBomWarning), 0);
  const TriangleMesh m = to_triangle_mesh(loaded);
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.positions.size(), 3u);
}

}  // namespace
}  // namespace lt
