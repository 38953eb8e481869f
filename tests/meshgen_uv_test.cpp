// meshgen's meshes with UVs (issue 13): the UV sphere against its closed-form positions, normals
// and UVs; the Utah teapot's patches, its atlas (no texel claimed twice, gutters a bake margin
// cannot cross) and its normals (unit, outward, one per position).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <vector>

#include "bake/uv_raster.h"
#include "mesh/mesh_io.h"
#include "mesh/meshgen.h"
#include "mesh/teapot_data.h"
#include "test_util.h"

namespace lt {
namespace {

struct Arrays {
  std::vector<glm::dvec3> positions, normals;
  std::vector<glm::dvec2> uvs;
  std::vector<glm::uvec3> triangles;
};

Arrays arrays_of(const PolyMesh& mesh) {
  Arrays a;
  for (auto vh : mesh.vertices()) {
    a.positions.push_back(to_glm(mesh.point(vh)));
    a.normals.push_back(to_glm(mesh.normal(vh)));
    a.uvs.push_back(to_glm(mesh.texcoord2D(vh)));
  }
  for (auto fh : mesh.faces()) {
    glm::uvec3 t;
    int k = 0;
    for (auto vh : mesh.fv_range(fh)) t[k++] = static_cast<unsigned>(vh.idx());
    EXPECT_EQ(k, 3);
    a.triangles.push_back(t);
  }
  return a;
}

double uv_area(const Arrays& a, const glm::uvec3& t) {
  const glm::dvec2 p = a.uvs[t.y] - a.uvs[t.x], q = a.uvs[t.z] - a.uvs[t.x];
  return p.x * q.y - p.y * q.x;
}

glm::dvec3 face_cross(const Arrays& a, const glm::uvec3& t) {
  return glm::cross(a.positions[t.y] - a.positions[t.x], a.positions[t.z] - a.positions[t.x]);
}

// ---------------------------------------------------------------------------------------------

TEST(UvSphereMesh, PositionsNormalsAndUvsAreAnalytic) {
  const int rings = 12, segments = 24;
  const Arrays a = arrays_of(meshgen::uv_sphere(2.0, rings));
  EXPECT_EQ(a.positions.size(),
            static_cast<std::size_t>(2 * segments + (rings - 1) * (segments + 1)));
  EXPECT_EQ(a.triangles.size(), static_cast<std::size_t>(2 * segments * (rings - 1)));
  const double pi = std::numbers::pi;
  std::size_t seam = 0;
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    const glm::dvec3& p = a.positions[v];
    const glm::dvec2& uv = a.uvs[v];
    EXPECT_NEAR(glm::length(p), 2.0, 1e-14);
    EXPECT_NEAR(glm::length(a.normals[v] - p / 2.0), 0.0, 1e-15) << v;
    // v = (latitude + pi/2) / pi.
    EXPECT_NEAR(uv.y, std::asin(std::clamp(p.y / 2.0, -1.0, 1.0)) / pi + 0.5, 1e-12) << v;
    if (uv.y == 0.0 || uv.y == 1.0) {
      // A pole: one vertex per segment, at the segment's middle u.
      EXPECT_EQ(p, glm::dvec3(0.0, uv.y == 0.0 ? -2.0 : 2.0, 0.0));
      EXPECT_NEAR(std::fmod(uv.x * segments, 1.0), 0.5, 1e-12);
      continue;
    }
    // u = longitude / 2 pi, longitude measured from +X towards -Z; the seam column has u = 1.
    double lon = std::atan2(-p.z, p.x) / (2 * pi);
    if (lon < 0) lon += 1.0;
    if (uv.x == 1.0) {
      ++seam;
      EXPECT_EQ(p.z, 0.0);
      EXPECT_GT(p.x, 0.0);
      lon = 1.0;
    }
    EXPECT_NEAR(uv.x, lon, 1e-12) << v;
  }
  EXPECT_EQ(seam, static_cast<std::size_t>(rings - 1));
  for (const auto& t : a.triangles) {
    // Outward (the centroid is on the outside of the face's plane through the centre) and
    // counter-clockwise in UV.
    const glm::dvec3 c = (a.positions[t.x] + a.positions[t.y] + a.positions[t.z]) / 3.0;
    EXPECT_GT(glm::dot(face_cross(a, t), c), 0.0);
    EXPECT_GT(uv_area(a, t), 0.0);
  }
}

// ---------------------------------------------------------------------------------------------

// The patches as connected pieces of the mesh: patches share no vertices.
std::size_t components(const Arrays& a, std::vector<std::size_t>& chart_of_triangle) {
  std::vector<std::size_t> parent(a.positions.size());
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : a.triangles) {
    parent[find(t.y)] = find(t.x);
    parent[find(t.z)] = find(t.x);
  }
  std::vector<std::size_t> id(a.positions.size(), 0);
  std::size_t n = 0;
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    if (find(v) == v) id[v] = n++;
  }
  chart_of_triangle.clear();
  for (const auto& t : a.triangles) chart_of_triangle.push_back(id[find(t.x)]);
  return n;
}

TEST(Teapot, PatchesAndCounts) {
  for (const int n : {3, 8}) {
    const Arrays a = arrays_of(meshgen::teapot(n));
    std::vector<std::size_t> chart;
    EXPECT_EQ(components(a, chart), static_cast<std::size_t>(meshgen::kTeapotPatches));
    // 8 patches (the lid's 4 around the knob, the bottom's 4) have an edge collapsed to a point,
    // where the row has one vertex and one triangle per cell.
    EXPECT_EQ(a.positions.size(), static_cast<std::size_t>(32 * (n + 1) * (n + 1) - 8));
    EXPECT_EQ(a.triangles.size(), static_cast<std::size_t>(32 * 2 * n * n - 8 * n));
    for (const auto& t : a.triangles) EXPECT_GT(glm::length(face_cross(a, t)), 0.0);
  }
}

TEST(Teapot, ChartsDoNotOverlapAndKeepTheirGutter) {
  const Arrays a = arrays_of(meshgen::teapot(meshgen::kDefaultTeapotSubdivisions));
  std::vector<std::size_t> chart;
  components(a, chart);
  for (const auto& uv : a.uvs) {
    EXPECT_GE(std::min(uv.x, uv.y), 0.0);
    EXPECT_LE(std::max(uv.x, uv.y), 1.0);
  }
  // Every chart counter-clockwise in UV, like its surface seen from outside.
  for (const auto& t : a.triangles) EXPECT_GT(uv_area(a, t), 0.0);
  const int size = 1024;
  const bake::UvCoverage c = bake::rasterize_uv(a.uvs, a.triangles, size, size);
  EXPECT_EQ(c.overlapping, 0u);
  EXPECT_GT(c.covered, static_cast<std::size_t>(size * size) / 3);  // the atlas is used
  // A margin of 4 texels around each chart must not meet another chart's margin: covered
  // texels of two charts are more than 8 apart (Chebyshev).
  constexpr int kReach = 2 * 4;
  std::vector<int> owner(c.triangle.size(), -1);
  for (std::size_t i = 0; i < c.triangle.size(); ++i) {
    if (c.triangle[i] >= 0)
      owner[i] = static_cast<int>(chart[static_cast<std::size_t>(c.triangle[i])]);
  }
  std::size_t too_close = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int me = owner[static_cast<std::size_t>(y) * size + x];
      if (me < 0) continue;
      for (int yy = std::max(0, y - kReach); yy <= std::min(size - 1, y + kReach); ++yy) {
        for (int xx = std::max(0, x - kReach); xx <= std::min(size - 1, x + kReach); ++xx) {
          const int other = owner[static_cast<std::size_t>(yy) * size + xx];
          if (other >= 0 && other != me) ++too_close;
        }
      }
    }
  }
  EXPECT_EQ(too_close, 0u);
}

TEST(Teapot, NormalsAreUnitOutwardAndOnePerPosition) {
  const Arrays a = arrays_of(meshgen::teapot(meshgen::kDefaultTeapotSubdivisions));
  for (const auto& n : a.normals) EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
  // The winding agrees with the normals at every corner.
  std::size_t disagree = 0;
  for (const auto& t : a.triangles) {
    const glm::dvec3 f = face_cross(a, t);
    for (int k = 0; k < 3; ++k) disagree += glm::dot(f, a.normals[t[k]]) <= 0.0;
  }
  EXPECT_EQ(disagree, 0u);
  // Outward: the surface's signed volume (divergence theorem; the gaps at the lid, spout and
  // handle ends are small) is positive, and from the body's centre most normals point away:
  // all of the body's and the bottom's (patches 4-11 and 28-31: a surface of revolution whose
  // profile's normal points away from the axis and, above half height, up, below it, down), and
  // most of the rest (the inner sides of the handle, the spout and the rim face the body).
  double volume = 0.0;
  for (const auto& t : a.triangles) {
    volume += glm::dot(a.positions[t.x], glm::cross(a.positions[t.y], a.positions[t.z])) / 6.0;
  }
  EXPECT_GT(volume, 0.0);
  std::vector<std::size_t> chart;
  components(a, chart);
  std::vector<std::size_t> chart_of_vertex(a.positions.size());
  for (std::size_t k = 0; k < a.triangles.size(); ++k) {
    for (int c = 0; c < 3; ++c) chart_of_vertex[a.triangles[k][c]] = chart[k];
  }
  const glm::dvec3 centre(0.0, 1.575, 0.0);  // half the height, on the body's axis
  std::size_t away = 0;
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    const bool out = glm::dot(a.normals[v], a.positions[v] - centre) > 0.0;
    away += out;
    const std::size_t patch = chart_of_vertex[v];
    if ((patch >= 4 && patch <= 11) || patch >= 28) EXPECT_TRUE(out) << "patch " << patch;
  }
  EXPECT_GT(2 * away, a.positions.size());
  // Copies of a point (patch borders, the knob's top, the bottom's centre) share one normal,
  // unless two surfaces meet there at an angle (the handle's end on the body): then their
  // normals are far apart.
  std::vector<std::size_t> order(a.positions.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t p, std::size_t q) { return a.positions[p].x < a.positions[q].x; });
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = i + 1; j < order.size(); ++j) {
      const auto& p = a.positions[order[i]];
      const auto& q = a.positions[order[j]];
      if (q.x - p.x > 1e-9) break;
      if (glm::length(q - p) > 1e-9) continue;
      ++pairs;
      const glm::dvec3 &m = a.normals[order[i]], &n = a.normals[order[j]];
      if (glm::dot(m, n) < std::cos(std::numbers::pi / 4)) continue;
      EXPECT_EQ(m, n) << p.x << " " << p.y << " " << p.z;
    }
  }
  EXPECT_GT(pairs, 0u);
  // The knob's top and the bottom's centre lie on the axis: their normal is the axis.
  for (std::size_t v = 0; v < a.positions.size(); ++v) {
    const auto& p = a.positions[v];
    if (std::hypot(p.x, p.z) > 1e-12) continue;
    if (std::abs(p.y - 3.15) < 1e-12) EXPECT_NEAR(a.normals[v].y, 1.0, 1e-9);
    if (std::abs(p.y) < 1e-12) EXPECT_NEAR(a.normals[v].y, -1.0, 1e-9);
  }
}

TEST(Teapot, WrittenWithItsUvsAndReadBack) {
  test::TempDir dir;
  const auto r = test::run_ltrender("meshgen " + dir.path().string() + " --teapot 4");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const TriangleMesh m = load_triangle_mesh(dir / "teapot.ply");
  const Arrays a = arrays_of(meshgen::teapot(4));
  EXPECT_EQ(m.positions, a.positions);
  ASSERT_EQ(m.uvs.size(), a.uvs.size());
  for (std::size_t v = 0; v < a.uvs.size(); ++v) {
    EXPECT_EQ(m.uvs[v], a.uvs[v]);  // double u, v: the atlas is not float-exact
  }
}

}  // namespace
}  // namespace lt
