// Polygons into triangles: convex faces keep the fan the goldens were rendered with; concave
// ones (issue 15: assimp's concave_polygon.obj rendered wrong) are cut into triangles that stay
// inside the polygon, checked by area and orientation against the polygon itself.
#include "mesh/triangulate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh/mesh_io.h"
#include "test_util.h"

namespace lt {
namespace {

using Tris = std::vector<std::array<std::size_t, 3>>;

// Shoelace area of a polygon in the XY plane, counter-clockwise positive.
double polygon_area_xy(const std::vector<glm::dvec3>& c) {
  double a = 0;
  for (std::size_t k = 0; k < c.size(); ++k) {
    const auto& p = c[k];
    const auto& q = c[(k + 1) % c.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a / 2;
}

// Signed area of each triangle seen along `normal`.
std::vector<double> signed_areas(const std::vector<glm::dvec3>& c, const Tris& tris,
                                 const glm::dvec3& normal) {
  std::vector<double> out;
  for (const auto& t : tris)
    out.push_back(glm::dot(glm::cross(c[t[1]] - c[t[0]], c[t[2]] - c[t[0]]), normal) / 2);
  return out;
}

TEST(Triangulate, ConvexPolygonsKeepTheFan) {
  const std::vector<glm::dvec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  Tris tris;
  triangulate_polygon(quad, tris);
  EXPECT_EQ(tris, (Tris{{0, 1, 2}, {0, 2, 3}}));
}

// An arrow-head (a "chevron"): corner 3 is reflex, so a fan from corner 0 would put the
// triangle (0, 2, 3) outside the polygon.
const std::vector<glm::dvec3> kChevron = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {2, 1, 0}, {0, 4, 0}};

TEST(Triangulate, AConcavePolygonIsCoveredExactlyOnce) {
  Tris tris;
  triangulate_polygon(kChevron, tris);
  ASSERT_EQ(tris.size(), kChevron.size() - 2);
  double sum = 0;
  for (double a : signed_areas(kChevron, tris, {0, 0, 1})) {
    EXPECT_GT(a, 0) << "a triangle with the wrong winding overlaps another";
    sum += a;
  }
  // Triangles of one winding whose areas add up to the polygon's cover it without overlap.
  EXPECT_DOUBLE_EQ(sum, polygon_area_xy(kChevron));
  // The fan would not: its areas add up to the polygon's only with a negative one among them.
  Tris fan = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  bool fan_has_negative = false;
  for (double a : signed_areas(kChevron, fan, {0, 0, 1})) fan_has_negative |= a < 0;
  EXPECT_TRUE(fan_has_negative);
}

TEST(Triangulate, FarFromTheOriginAndTiltedTheSame) {
  // The chevron rotated about x by 30 degrees and moved to 1e6: the projection onto its own
  // plane and Newell's normal keep it exact to rounding.
  const double c = std::cos(0.5236), s = std::sin(0.5236);
  std::vector<glm::dvec3> moved;
  for (const auto& p : kChevron) moved.push_back({p.x + 1e6, p.y * c + 1e6, p.y * s - 1e6});
  Tris tris;
  triangulate_polygon(moved, tris);
  ASSERT_EQ(tris.size(), 3u);
  const glm::dvec3 normal(0, -s, c);
  double sum = 0;
  for (double a : signed_areas(moved, tris, normal)) {
    EXPECT_GT(a, 0);
    sum += a;
  }
  EXPECT_NEAR(sum, polygon_area_xy(kChevron), 1e-6);
}

TEST(Triangulate, AConcaveObjFaceRendersInsideItsOutline) {
  test::TempDir dir;
  test::write_file(dir / "chevron.obj",
                   "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 2 1 0\nv 0 4 0\nf 1 2 3 4 5\n");
  const TriangleMesh m = load_triangle_mesh(dir / "chevron.obj");
  ASSERT_EQ(m.triangles.size(), 3u);
  double sum = 0;
  for (const auto& t : m.triangles) {
    const double a =
        glm::cross(m.positions[t.y] - m.positions[t.x], m.positions[t.z] - m.positions[t.x]).z / 2;
    EXPECT_GT(a, 0);
    sum += a;
  }
  EXPECT_DOUBLE_EQ(sum, 10.0);  // 4x4 square minus the notch (0,4)-(2,1)-(4,4): 16 - 6
}

}  // namespace
}  // namespace lt
