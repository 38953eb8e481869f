// The UV-space thickness bake_uv_surface (issue 13): the analytic sphere through its texels,
// agreement with the vertex bake at the vertices, the rasteriser's coverage and overlap counts, the
// margin, and the command's contract (a mesh without UVs is refused, nothing is written).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include "bake/uv_baker.h"
#include "bake/uv_raster.h"
#include "bake_bounds.h"
#include "image/image.h"
#include "mesh/mesh_io.h"
#include "mesh/meshgen.h"
#include "test_util.h"

namespace lt::bake {
namespace {

struct UvSurface {
  Surface surface;
  std::vector<glm::dvec2> uvs;
};

UvSurface uv_surface(const PolyMesh& mesh) {
  UvSurface s{surface_of(mesh), {}};
  for (auto vh : mesh.vertices()) s.uvs.push_back(to_glm(mesh.texcoord2D(vh)));
  return s;
}

UvBakeResult bake_uv_surface(const UvSurface& s, const BakeSettings& settings, int w, int h,
                             int margin = 0) {
  return bake_uv(s.surface.positions, s.surface.normals, s.uvs, s.surface.triangles, settings, w, h,
                 margin);
}

double covered_mean(const UvBakeResult& r) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < r.occlusion.size(); ++i) {
    if (!r.filled[i]) continue;
    sum += r.occlusion[i];
    ++n;
  }
  return sum / static_cast<double>(n);
}

// ---------------------------------------------------------------------------------------------
// The analytic sphere (bake_bounds.h): meshgen's UV sphere has radial vertex normals (n = p / R),
// so a texel's interpolated normal is radial too and only its depth below the sphere (at most
// the sagitta) differs from a vertex's.

class UvSphere : public ::testing::TestWithParam<double> {};

TEST_P(UvSphere, TexelsMatchTheChordLength) {
  const double d = GetParam();
  const UvSurface s = uv_surface(meshgen::uv_sphere(1.0, 64));
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = d;
  settings.seed = 11;
  const UvBakeResult r = bake_uv_surface(s, settings, 256, 128);
  ASSERT_GT(r.covered, 256u * 128u * 9 / 10);  // the poles' fans leave a few texels out
  EXPECT_EQ(r.overlapping, 0u);
  const double sag = sagitta(s.surface, glm::dvec3(0.0), 1.0);
  const Expected e = sphere_occlusion(1.0, d, r.epsilon, sag, Distribution::Cosine, sag);
  const double analytic = analytic_sphere_occlusion(1.0, d, Distribution::Cosine);
  const double tol = 5.0 * binomial_sigma(analytic, static_cast<double>(r.covered) * settings.rays);
  const double m = covered_mean(r);
  EXPECT_GE(m, e.lo - tol) << "analytic " << analytic << ", sandwich [" << e.lo << ", " << e.hi
                           << "], 5 sigma " << tol;
  EXPECT_LE(m, e.hi + tol) << "analytic " << analytic << ", sandwich [" << e.lo << ", " << e.hi
                           << "], 5 sigma " << tol;
}

INSTANTIATE_TEST_SUITE_P(D, UvSphere, ::testing::Values(0.5, 1.0, 1.5));

// Both bakes estimate the same expectation at a vertex and at the texel that holds its UV (both
// lie in the sandwich), each from 256 rays: they differ by at most the sandwich's width plus
// 5 sigma of the difference of two independent estimates.
TEST(UvBake, AgreesWithTheVertexBakeAtTheVertices) {
  const PolyMesh mesh = meshgen::uv_sphere(1.0, 16);
  const UvSurface s = uv_surface(mesh);
  BakeSettings settings;
  settings.rays = 256;
  settings.max_distance = 1.0;
  settings.seed = 5;
  const BakeResult vertex =
      bake_occlusion(s.surface.positions, s.surface.normals, s.surface.triangles, settings);
  const int w = 512, h = 256;
  const UvBakeResult texel = bake_uv_surface(s, settings, w, h);
  const double sag = sagitta(s.surface, glm::dvec3(0.0), 1.0);
  const Expected e = sphere_occlusion(1.0, 1.0, texel.epsilon, sag, Distribution::Cosine, sag);
  const double analytic = analytic_sphere_occlusion(1.0, 1.0, Distribution::Cosine);
  const double bound = (e.hi - e.lo) + 5.0 * std::sqrt(2.0) * binomial_sigma(analytic, 256);
  std::size_t compared = 0;
  for (std::size_t v = 0; v < s.uvs.size(); ++v) {
    const int x = std::clamp(static_cast<int>(s.uvs[v].x * w), 0, w - 1);
    const int y = std::clamp(static_cast<int>((1.0 - s.uvs[v].y) * h), 0, h - 1);
    const std::size_t i = static_cast<std::size_t>(y) * w + static_cast<std::size_t>(x);
    if (!texel.filled[i]) continue;  // a pole vertex: its fan's tip covers no texel centre
    ++compared;
    EXPECT_NEAR(texel.occlusion[i], vertex.occlusion[v], bound) << "vertex " << v;
  }
  // Every vertex but the 2 x 32 at the poles has a covered texel.
  EXPECT_GE(compared, s.uvs.size() - 64);
}

TEST(UvBake, SameMapOnOneAndTwoThreads) {
  const UvSurface s = uv_surface(meshgen::uv_sphere(1.0, 12));
  BakeSettings settings;
  settings.rays = 16;
  settings.seed = 9;
  for (const Sampler sampler : {Sampler::Stratified, Sampler::Random}) {
    settings.sampler = sampler;
    settings.threads = 1;
    const UvBakeResult one = bake_uv_surface(s, settings, 64, 32, 2);
    settings.threads = 2;
    const UvBakeResult two = bake_uv_surface(s, settings, 64, 32, 2);
    EXPECT_EQ(one.threads, 1);
    EXPECT_EQ(two.threads, 2);
    EXPECT_EQ(one.occlusion, two.occlusion);
    EXPECT_EQ(one.filled, two.filled);
  }
}

// ---------------------------------------------------------------------------------------------
// Rasterising in UV space.

// The texel centres strictly inside a UV triangle, counted by brute force with plain double
// barycentrics (the fixtures put no centre on an edge).
std::vector<char> inside(const glm::dvec2 a, const glm::dvec2 b, const glm::dvec2 c, int w, int h) {
  std::vector<char> in(static_cast<std::size_t>(w) * h, 0);
  auto side = [](glm::dvec2 p, glm::dvec2 q, glm::dvec2 r) {
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const glm::dvec2 p((x + 0.5) / w, 1.0 - (y + 0.5) / h);
      const double s0 = side(a, b, p), s1 = side(b, c, p), s2 = side(c, a, p);
      in[static_cast<std::size_t>(y) * w + x] =
          (s0 > 0 && s1 > 0 && s2 > 0) || (s0 < 0 && s1 < 0 && s2 < 0);
    }
  }
  return in;
}

std::size_t count(const std::vector<char>& v) {
  return static_cast<std::size_t>(std::count(v.begin(), v.end(), 1));
}

TEST(UvRaster, OverlapsAreCountedExactly) {
  const int w = 64, h = 64;
  // Two triangles whose UVs overlap in part (B is A shifted by (0.2, 0.15)); no texel centre
  // (k + 0.5) / 64 lies on an edge.
  const glm::dvec2 a0(0.1, 0.1), a1(0.7, 0.1), a2(0.1, 0.7);
  const glm::dvec2 d(0.2, 0.15);
  const std::vector<glm::dvec2> uvs = {a0, a1, a2, a0 + d, a1 + d, a2 + d};
  const std::vector<glm::uvec3> tris = {{0, 1, 2}, {3, 4, 5}};
  const UvCoverage c = rasterize_uv(uvs, tris, w, h);
  const auto in_a = inside(a0, a1, a2, w, h), in_b = inside(a0 + d, a1 + d, a2 + d, w, h);
  std::vector<char> both(in_a.size()), either(in_a.size());
  for (std::size_t i = 0; i < in_a.size(); ++i) {
    both[i] = in_a[i] && in_b[i];
    either[i] = in_a[i] || in_b[i];
  }
  ASSERT_GT(count(both), 100u);
  EXPECT_EQ(c.overlapping, count(both));
  EXPECT_EQ(c.covered, count(either));
  // The overlap keeps the first triangle.
  for (std::size_t i = 0; i < both.size(); ++i) {
    if (both[i]) EXPECT_EQ(c.triangle[i], 0);
  }
}

TEST(UvRaster, ASharedEdgeThroughTexelCentresIsDrawnOnce) {
  // The unit square as two triangles: the diagonal from (0, 0) to (1, 1) passes through the
  // centres of the 4 texels with x + y = 3 in a 4 x 4 map, the square's border through none.
  const std::vector<glm::dvec2> uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (const auto& tris : {std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}},
                           std::vector<glm::uvec3>{{0, 2, 1}, {0, 3, 2}}}) {
    const UvCoverage c = rasterize_uv(uvs, tris, 4, 4);
    EXPECT_EQ(c.covered, 16u);
    EXPECT_EQ(c.overlapping, 0u);
  }
  // With the other diagonal, through the centres with x == y.
  const UvCoverage c = rasterize_uv(uvs, {{0, 1, 3}, {1, 2, 3}}, 4, 4);
  EXPECT_EQ(c.covered, 16u);
  EXPECT_EQ(c.overlapping, 0u);
}

TEST(UvRaster, VZeroIsTheBottomRow) {
  // A small triangle near (u, v) = (0.1, 0.1): in a 10 x 10 map, column 1 and image row 8
  // (row (1 - v) * H, counted from the top).
  const std::vector<glm::dvec2> uvs = {{0.11, 0.11}, {0.19, 0.11}, {0.11, 0.195}};
  const UvCoverage c = rasterize_uv(uvs, {{0, 1, 2}}, 10, 10);
  ASSERT_EQ(c.covered, 1u);
  EXPECT_EQ(c.triangle[8 * 10 + 1], 0);
  // Its barycentrics interpolate the texel centre (0.15, 0.15) exactly.
  const glm::dvec3 b = c.barycentric[8 * 10 + 1];
  const glm::dvec2 p = b.x * uvs[0] + b.y * uvs[1] + b.z * uvs[2];
  EXPECT_NEAR(p.x, 0.15, 1e-12);
  EXPECT_NEAR(p.y, 0.15, 1e-12);
}

// ---------------------------------------------------------------------------------------------
// The margin.

TEST(UvMargin, EachPassTakesTheMeanOfItsFilledNeighbours) {
  // Two filled texels on row 2 of a 7 x 5 map, values 0 and 1, two columns apart.
  const int w = 7, h = 5;
  std::vector<double> values(w * h, 0.0);
  std::vector<char> filled(w * h, 0);
  filled[2 * w + 2] = 1;
  filled[2 * w + 4] = 1;
  values[2 * w + 4] = 1.0;
  EXPECT_EQ(dilate(values, filled, w, h, 1), 13u);  // two 3 x 3 blocks sharing a column
  EXPECT_DOUBLE_EQ(values[2 * w + 3], 0.5);         // between them: both neighbours
  EXPECT_DOUBLE_EQ(values[1 * w + 3], 0.5);
  EXPECT_DOUBLE_EQ(values[2 * w + 1], 0.0);  // only the 0
  EXPECT_DOUBLE_EQ(values[2 * w + 5], 1.0);  // only the 1
}

// After N passes, exactly the texels within Chebyshev distance N of the covered ones are
// filled, computed here by brute force over the coverage.
TEST(UvMargin, FillsExactlyNTexelsBeyondCoverage) {
  const int w = 48, h = 40;
  // One triangle (open: its rays escape) in the middle of the map, without file normals.
  const std::vector<glm::dvec3> positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<glm::dvec3> normals(3, glm::dvec3(0.0));
  const std::vector<glm::dvec2> uvs = {{0.3, 0.3}, {0.62, 0.35}, {0.4, 0.71}};
  const std::vector<glm::uvec3> tris = {{0, 1, 2}};
  BakeSettings settings;
  settings.rays = 4;
  const UvBakeResult plain = bake_uv(positions, normals, uvs, tris, settings, w, h, 0);
  for (const int n : {1, 3, 6}) {
    const UvBakeResult r = bake_uv(positions, normals, uvs, tris, settings, w, h, n);
    std::size_t expected_margin = 0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        int nearest = 1 << 20;
        for (int yy = 0; yy < h; ++yy) {
          for (int xx = 0; xx < w; ++xx) {
            if (plain.filled[static_cast<std::size_t>(yy) * w + xx]) {
              nearest = std::min(nearest, std::max(std::abs(xx - x), std::abs(yy - y)));
            }
          }
        }
        const bool want = nearest <= n;
        if (want && nearest > 0) ++expected_margin;
        EXPECT_EQ(r.filled[static_cast<std::size_t>(y) * w + x] != 0, want)
            << "texel " << x << "," << y << " at distance " << nearest << ", margin " << n;
      }
    }
    EXPECT_EQ(r.margin, expected_margin);
    EXPECT_EQ(r.covered, plain.covered);
  }
}

// ---------------------------------------------------------------------------------------------
// The command.

TEST(BakeTexture, MeshWithoutUvsIsRefusedAndNothingIsWritten) {
  test::TempDir dir;
  const fs::path cube = test::source_dir() / "meshes" / "cube.ply";
  const auto r = test::run_ltrender("bake " + cube.string() + " --texture 16x16 -o " +
                                    (dir / "map.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(cube.string()), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("has no texture coordinates"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "map.png"));
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(BakeTexture, BadSizesAndOptionsExitTwo) {
  test::TempDir dir;
  const fs::path sphere = test::source_dir() / "meshes" / "uvsphere.ply";
  for (const std::string args : {"--texture 0x16", "--texture 16", "--texture 16x16x2",
                                 "--texture 99999x2", "--texture 16x16 --margin -1",
                                 "--texture 16x16 --smooth 2", "--texture 16x16 --float-colors"}) {
    const auto r = test::run_ltrender("bake " + sphere.string() + " " + args + " -o " +
                                      (dir / "map.png").string());
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
  }
  const auto r = test::run_ltrender("bake " + sphere.string() + " --texture 16x16 -o " +
                                    (dir / "map.ply").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(fs::is_empty(dir.path()));
}

TEST(BakeTexture, WritesPngAndExrAndWarnsAboutOverlaps) {
  test::TempDir dir;
  // A tetrahedron whose four faces all use the same UV triangle: every covered texel but those
  // of the first face is claimed again.
  test::write_file(dir / "tet.ply",
                   "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                   "property float z\nproperty float u\nproperty float v\nelement face 4\n"
                   "property list uchar int vertex_indices\nend_header\n"
                   "0 0 1 0.1 0.1\n1 0 -1 0.9 0.1\n-1 0 -1 0.5 0.9\n0 1.5 0 0.5 0.9\n"
                   "3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n");
  const auto r =
      test::run_ltrender("bake " + (dir / "tet.ply").string() +
                         " --texture 32x32 --rays 8 --margin 1 -o " + (dir / "map.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TriangleMesh mesh = load_triangle_mesh(dir / "tet.ply");
  const UvCoverage c = rasterize_uv(mesh.uvs, mesh.triangles, 32, 32);
  ASSERT_GT(c.overlapping, 0u);
  EXPECT_NE(r.err.find(std::to_string(c.overlapping) + " texels are covered by two or more"),
            std::string::npos)
      << r.err;
  const Image png = read_image(dir / "map.png");
  EXPECT_EQ(png.width, 32);
  EXPECT_EQ(png.height, 32);
  const auto e =
      test::run_ltrender("bake " + (dir / "tet.ply").string() +
                         " --texture 32x32 --rays 8 --margin 1 -o " + (dir / "map.exr").string());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const Image exr = read_image(dir / "map.exr");
  // The PNG is the EXR's values in 8 bits, linear (no sRGB curve).
  for (std::size_t i = 0; i < png.rgba.size(); i += 4) {
    EXPECT_NEAR(png.rgba[i], to_unorm8(exr.rgba[i]) / 255.0f, 1e-7) << i / 4;
  }
}

}  // namespace
}  // namespace lt::bake
