// Thickness baker (issue 3): analytic expectations first (a sphere's chord lengths give its
// occlusion in closed form), then orderings the GDC addendum describes, determinism, and the
// command's contract for bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

#include "bake/thickness_baker.h"
#include "bake_bounds.h"
#include "core/error.h"
#include "mesh/mesh_io.h"
#include "mesh/meshgen.h"
#include "test_util.h"

namespace lt::bake {
namespace {

namespace fs = std::filesystem;

// ---------------------------------------------------------------------------------------------
// Meshes on plain arrays (the baker's core input).

// meshgen's geodesic sphere: vertices exactly on the sphere, normals exactly radial, so the
// analytic tests check the baker, not a normal estimator.
Surface icosphere(double radius, int subdivisions, const glm::dvec3& centre = glm::dvec3(0.0)) {
  Surface s = surface_of(meshgen::icosphere(radius, subdivisions));
  for (auto& p : s.positions) p += centre;
  return s;
}

// meshgen's box: each face an n x n grid with its own vertices and flat normals, so corners and
// edges are split (three and two vertices at one position), as exported hard-edged meshes are.
Surface box(const glm::dvec3& half, int n) {
  return surface_of(meshgen::box(half, n));
}

BakeResult bake_surface(const Surface& s, const BakeSettings& settings) {
  return bake_occlusion(s.positions, s.normals, s.triangles, settings);
}

double mean(const std::vector<double>& v) {
  return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
}

// ---------------------------------------------------------------------------------------------
// The analytic sphere: see bake_bounds.h for the chord argument and its sandwich bounds.

struct SphereCase {
  double radius, d;
  Distribution distribution;
  Sampler sampler;
};

// "R1_D0.5_cosine_stratified", readable in test names and failure messages.
std::string sphere_case_name(const SphereCase& c) {
  std::ostringstream out;
  out << "R" << c.radius << "_D" << c.d << "_"
      << (c.distribution == Distribution::Cosine ? "cosine" : "uniform") << "_"
      << (c.sampler == Sampler::Stratified ? "stratified" : "random");
  return out.str();
}
void PrintTo(const SphereCase& c, std::ostream* os) {
  *os << sphere_case_name(c);
}

class AnalyticSphere : public ::testing::TestWithParam<SphereCase> {};

// 40962 vertices x 64 rays: 2.6 M rays, so 5 sigma of the mean is at most 1.6e-3. The sagitta
// of this subdivision is 5e-5 R, which moves the expectation by ~1e-4 (cosine) to ~3e-4
// (uniform, small D): the sandwich bounds account for it exactly.
TEST_P(AnalyticSphere, OcclusionMatchesChordLength) {
  const SphereCase c = GetParam();
  const Surface s = icosphere(c.radius, 6);
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = c.d;
  settings.distribution = c.distribution;
  settings.sampler = c.sampler;
  settings.seed = 7;
  const BakeResult r = bake_surface(s, settings);

  const Expected e = sphere_occlusion(c.radius, c.d, r.epsilon,
                                      sagitta(s, glm::dvec3(0.0), c.radius), c.distribution);
  const double analytic = analytic_sphere_occlusion(c.radius, c.d, c.distribution);
  const double n = static_cast<double>(s.positions.size()) * settings.rays;
  const double tol = 5.0 * binomial_sigma(analytic, n);
  const double m = mean(r.occlusion);
  EXPECT_GE(m, e.lo - tol) << "analytic " << analytic << ", sandwich [" << e.lo << ", " << e.hi
                           << "], 5 sigma " << tol;
  EXPECT_LE(m, e.hi + tol) << "analytic " << analytic << ", sandwich [" << e.lo << ", " << e.hi
                           << "], 5 sigma " << tol;
  // The sandwich is tight: the polyhedron and the eps offset change the answer by < 1e-3.
  EXPECT_NEAR(e.lo, analytic, 5e-4);
  EXPECT_LT(e.hi - e.lo, 1e-3);

  if (c.sampler == Sampler::Stratified) {
    // Stratification is in cos(theta): the N rays of one vertex put exactly floor or ceil of
    // N * P(cos(theta) < x) rays below any threshold x. So every single vertex, not just the
    // mean, is within 1/N of the sandwich (plus one more ray for the near-tangent rays the
    // polyhedron's neighbouring faces catch before eps).
    const double slack = 2.0 / settings.rays;
    const auto [lo, hi] = std::minmax_element(r.occlusion.begin(), r.occlusion.end());
    EXPECT_GE(*lo, e.lo - slack);
    EXPECT_LE(*hi, e.hi + slack);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Bake, AnalyticSphere,
    ::testing::Values(SphereCase{1.0, 0.5, Distribution::Cosine, Sampler::Stratified},
                      SphereCase{1.0, 1.2, Distribution::Cosine, Sampler::Stratified},
                      SphereCase{2.5, 4.0, Distribution::Cosine, Sampler::Stratified},
                      SphereCase{1.0, 0.2, Distribution::Uniform, Sampler::Stratified},
                      SphereCase{1.0, 1.5, Distribution::Uniform, Sampler::Stratified},
                      SphereCase{3.0, 2.0, Distribution::Cosine, Sampler::Random},
                      SphereCase{1.0, 0.7, Distribution::Uniform, Sampler::Random}),
    [](const ::testing::TestParamInfo<SphereCase>& info) {
      std::string name = sphere_case_name(info.param);
      std::replace(name.begin(), name.end(), '.', 'p');  // test names are identifiers
      return name;
    });

// A max distance longer than the diameter: every chord is shorter, every ray hits.
TEST(Bake, SphereWithMaxDistanceBeyondTheDiameterIsFullyOccluded) {
  const Surface s = icosphere(1.0, 5);
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = 2.5;
  const BakeResult r = bake_surface(s, settings);
  EXPECT_EQ(*std::min_element(r.occlusion.begin(), r.occlusion.end()), 1.0);
}

// No self-hits: with D far below the radius only rays within ~D/2R of tangent could hit
// anything, i.e. (D/2R)^2 = 2.5e-7 of cosine rays; a ray hitting its own triangles would show up
// as occlusion ~0.5. On the polyhedron a ray that starts eps inside needs at least
// eps / (face tilt) = 3.5e-5 / 8e-3 R = 4e-3 R to reach a neighbouring face: so exactly zero.
TEST(Bake, NoSelfHitsOnAFinelyTessellatedSphere) {
  for (const Distribution dist : {Distribution::Cosine, Distribution::Uniform}) {
    const Surface s = icosphere(1.0, 6);
    BakeSettings settings;
    settings.rays = 64;
    settings.max_distance = 1e-3;
    settings.distribution = dist;
    const BakeResult r = bake_surface(s, settings);
    EXPECT_EQ(*std::max_element(r.occlusion.begin(), r.occlusion.end()), 0.0);
  }
}

// Far from the origin (coordinates near 1e6) and tiny (1e-6): positions go to Embree relative to
// the box centre and eps scales with the mesh, so the answer does not change.
TEST(Bake, SphereAnswerIsTheSameFarFromTheOriginAndAtTinyScale) {
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance_relative = 0.25;
  const double expected = std::pow(0.25 * 2.0 * std::sqrt(3.0) / 2.0, 2);  // D/2R, R = 1
  for (const auto& [radius, centre] :
       {std::pair{1.0, glm::dvec3(1e6, -1e6, 1e6)}, std::pair{1e-6, glm::dvec3(0.0)}}) {
    const Surface s = icosphere(radius, 5, centre);
    const BakeResult r = bake_surface(s, settings);
    // 5 sigma of a binomial over 10242 x 64 rays (the stratified sampler does far better).
    EXPECT_NEAR(mean(r.occlusion), expected, 2.5e-3) << "radius " << radius;
  }
}

// Distance estimator: 1 - E[min(chord, D)] / D. With cosine sampling (pdf of x = cos(theta) is
// 2x) and a = D/2R <= 1: E[min(2R x, D)] = D (1 - a^2/3), so the estimate is a^2/3. Bounds: the
// same sphere sandwich, integrated numerically.
TEST(Bake, DistanceEstimatorMatchesMeanChordOnASphere) {
  const double radius = 1.0, d = 1.0;
  const Surface s = icosphere(radius, 6);
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = d;
  settings.estimator = Estimator::Distance;
  const BakeResult r = bake_surface(s, settings);
  const double a = d / (2 * radius);
  const double analytic = a * a / 3.0;

  const double rho = radius - r.epsilon;
  auto estimate = [&](double sphere) {  // 1 - E[min(c, D)]/D for a sphere of radius `sphere`
    const int steps = 200000;
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
      const double x = (i + 0.5) / steps;
      const double c =
          rho * x + std::sqrt(std::max(0.0, sphere * sphere - rho * rho * (1 - x * x)));
      sum += std::min(c, d) * 2.0 * x / steps;
    }
    return 1.0 - sum / d;
  };
  const double lo = estimate(radius);
  const double hi = estimate(radius - sagitta(s, glm::dvec3(0.0), radius));
  EXPECT_NEAR(lo, analytic, 1e-4);  // the eps offset shortens chords a little
  // Per-ray values lie in [0, 1]: their standard deviation is at most 1/2.
  const double tol = 5.0 * 0.5 / std::sqrt(double(s.positions.size()) * settings.rays);
  EXPECT_GE(mean(r.occlusion), lo - tol);
  EXPECT_LE(mean(r.occlusion), hi + tol);
}

// ---------------------------------------------------------------------------------------------
// Orderings from the talk and the addendum.

// "Thinner parts of the mesh are more translucent than generally thicker parts."
TEST(Bake, ThinSlabIsMoreTranslucentThanAThickBlock) {
  BakeSettings settings;
  settings.rays = 128;
  settings.max_distance = 0.5;
  const Surface slab = box({1.0, 1.0, 0.05}, 8);
  const Surface block = box({1.0, 1.0, 1.0}, 8);
  const BakeResult rs = bake_surface(slab, settings);
  const BakeResult rb = bake_surface(block, settings);
  // Centre of the top face: the opposite wall is 0.1 away on the slab (every ray with
  // cos(theta) > 0.2 hits: occlusion ~ 1 - 0.04), 2 away on the block (nothing within 0.5).
  auto top_centre = [](const Surface& s) {
    for (std::size_t i = 0; i < s.positions.size(); ++i) {
      const auto& p = s.positions[i];
      if (p.x == 0.0 && p.y == 0.0 && p.z > 0.0) return i;
    }
    return std::size_t(-1);
  };
  const std::size_t ts = top_centre(slab), tb = top_centre(block);
  ASSERT_NE(ts, std::size_t(-1));
  ASSERT_NE(tb, std::size_t(-1));
  EXPECT_NEAR(rs.occlusion[ts], 0.96, 0.02);
  EXPECT_EQ(rb.occlusion[tb], 0.0);
  EXPECT_GT(mean(rs.occlusion), mean(rb.occlusion) + 0.5);

  const ColorMap map{0.5, 1.0, {1.0, 0.2, 0.1}};  // the addendum's 50% grey floor, red skin tint
  EXPECT_GT(translucency(rs.occlusion[ts], map).r, translucency(rb.occlusion[tb], map).r);
}

// Addendum: with flipped normals "you will end up with a different value at each vertex, because
// the inner faces that meet at each vertex create occlusion between each other": at a corner
// three inner faces meet, at an edge two, at a face centre none is near. meshgen's box splits its
// corners (3 copies) and edges (2 copies): every copy must get the same value.
TEST(Bake, CubeCornersAreMoreOccludedThanEdgesThanFaceCentres) {
  const Surface cube = box({1.0, 1.0, 1.0}, 8);
  BakeSettings settings;
  settings.rays = 256;
  settings.max_distance = 1.0;
  const BakeResult r = bake_surface(cube, settings);
  std::vector<double> corner, edge, face;
  for (std::size_t i = 0; i < cube.positions.size(); ++i) {
    const glm::dvec3 a = glm::abs(cube.positions[i]);
    const int on_faces = (a.x == 1.0) + (a.y == 1.0) + (a.z == 1.0);
    const int zeros = (a.x == 0.0) + (a.y == 0.0) + (a.z == 0.0);
    if (on_faces == 3) corner.push_back(r.occlusion[i]);
    if (on_faces == 2 && zeros == 1) edge.push_back(r.occlusion[i]);
    if (on_faces == 1 && zeros == 2) face.push_back(r.occlusion[i]);
  }
  ASSERT_EQ(corner.size(), 8u * 3u);
  ASSERT_EQ(edge.size(), 12u * 2u);
  ASSERT_EQ(face.size(), 6u);
  // Copies at one position share their rays: vertex i and the copy found at the same position.
  for (std::size_t i = 0; i < cube.positions.size(); ++i) {
    for (std::size_t j = i + 1; j < cube.positions.size(); ++j) {
      if (cube.positions[i] == cube.positions[j]) EXPECT_EQ(r.occlusion[i], r.occlusion[j]);
    }
  }
  // By symmetry all corners see the same geometry; they differ only by sampling noise.
  EXPECT_GT(mean(corner), mean(edge) + 0.05);
  EXPECT_GT(mean(edge), mean(face) + 0.05);
  EXPECT_LT(mean(face), 0.01);  // the nearest wall is 1 away, reachable only at grazing angles
}

// ---------------------------------------------------------------------------------------------
// Determinism and robustness.

TEST(Bake, SameSeedGivesTheSameResultOnAnyThreadCount) {
  const Surface s = icosphere(1.0, 4);
  for (const Sampler sampler : {Sampler::Stratified, Sampler::Random}) {
    BakeSettings settings;
    settings.rays = 32;
    settings.sampler = sampler;
    settings.seed = 1234;
    settings.threads = 1;
    const BakeResult one = bake_surface(s, settings);
    settings.threads = 2;
    const BakeResult two = bake_surface(s, settings);
    settings.threads = 3;
    const BakeResult three = bake_surface(s, settings);
    EXPECT_EQ(one.occlusion, two.occlusion);
    EXPECT_EQ(one.occlusion, three.occlusion);
    settings.seed = 1235;
    EXPECT_NE(bake_surface(s, settings).occlusion, one.occlusion);
  }
}

TEST(Bake, ZeroNormalsFallBackToFaceNormals) {
  Surface s = icosphere(1.0, 4);
  BakeSettings settings;
  settings.rays = 32;
  settings.max_distance = 1.0;
  const BakeResult radial = bake_surface(s, settings);
  std::fill(s.normals.begin(), s.normals.end(), glm::dvec3(0.0));
  s.normals[0] = glm::dvec3(std::nan(""), 0.0, 0.0);
  // An isolated vertex with no normal: no rays, occlusion 0, counted.
  s.positions.push_back(glm::dvec3(0.0));
  s.normals.push_back(glm::dvec3(0.0));
  const BakeResult fallback = bake_surface(s, settings);
  EXPECT_EQ(fallback.vertices_without_normal, 1u);
  EXPECT_EQ(fallback.occlusion.back(), 0.0);
  EXPECT_EQ(fallback.rays_traced, (s.positions.size() - 1) * 32u);
  // Face-averaged normals of a geodesic sphere are within ~1e-3 rad of radial.
  for (std::size_t i = 0; i + 1 < s.positions.size(); ++i) {
    EXPECT_NEAR(fallback.occlusion[i], radial.occlusion[i], 2.0 / 32) << i;
  }
}

TEST(Bake, DegenerateTrianglesAndOpenMeshesWork) {
  Surface s = box({1.0, 1.0, 1.0}, 4);
  // Open the box: drop the last face's 4 x 4 x 2 triangles (its vertices stay, unreferenced).
  s.triangles.resize(s.triangles.size() - 32);
  const EdgeReport edges = count_problem_edges(s.positions, s.triangles);
  EXPECT_EQ(edges.boundary_edges, 4u * 4u);  // the rim of the missing 4 x 4 face
  EXPECT_EQ(edges.non_manifold_edges, 0u);

  // Degenerate triangles: a repeated index, and three collinear points of their own.
  s.triangles.push_back({0, 0, 1});
  s.positions.push_back({0.0, 0.0, 0.0});
  s.positions.push_back({0.25, 0.0, 0.0});
  s.positions.push_back({0.5, 0.0, 0.0});
  s.normals.insert(s.normals.end(), 3, glm::dvec3(0.0));
  const unsigned n = static_cast<unsigned>(s.positions.size());
  s.triangles.push_back({n - 3, n - 2, n - 1});

  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = 1.0;
  const BakeResult r = bake_surface(s, settings);
  for (double o : r.occlusion) {
    EXPECT_GE(o, 0.0);
    EXPECT_LE(o, 1.0);
  }
  EXPECT_EQ(r.vertices_without_normal, 3u);  // the collinear triangle has no area
}

TEST(Bake, EdgeCountsWeldByPositionAndFindNonManifoldEdges) {
  // Two triangles sharing an edge through split (duplicated) vertices: not a boundary there.
  const std::vector<glm::dvec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0},
                                     {0, 1, 0}, {1, 1, 0}, {0, 0, 1}};
  EdgeReport e = count_problem_edges(p, {{0, 1, 2}, {3, 5, 4}});
  EXPECT_EQ(e.boundary_edges, 4u);
  EXPECT_EQ(e.non_manifold_edges, 0u);
  // A third triangle on the shared edge (1,2): non-manifold.
  e = count_problem_edges(p, {{0, 1, 2}, {3, 5, 4}, {1, 6, 2}});
  EXPECT_EQ(e.non_manifold_edges, 1u);
  EXPECT_EQ(
      count_problem_edges(box({1, 1, 1}, 3).positions, box({1, 1, 1}, 3).triangles).boundary_edges,
      0u);
}

// meshgen's degenerate sphere: closed, with zero-area slivers (collinear, or with a corner
// duplicated at one position). Slivers are not holes, and they bake like the sphere around them.
TEST(Bake, DegenerateSliversAreNeitherHolesNorNonManifoldAndBakeLikeTheSphere) {
  const Surface s = surface_of(meshgen::degenerate_sphere(3, 24));
  const EdgeReport e = count_problem_edges(s.positions, s.triangles);
  EXPECT_EQ(e.boundary_edges, 0u);
  EXPECT_EQ(e.non_manifold_edges, 0u);
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = 1.0;
  const BakeResult r = bake_surface(s, settings);
  // (D/2R)^2 = 0.25; a subdivision-3 sphere has a sagitta of 3e-3 R, and each vertex is within
  // 2/64 of the sandwich (see AnalyticSphere).
  for (double o : r.occlusion) EXPECT_NEAR(o, 0.25, 0.05);
  EXPECT_EQ(r.vertices_without_normal, 0u);
}

TEST(Bake, EmptyInputGivesAnEmptyResult) {
  EXPECT_TRUE(bake_occlusion({}, {}, {}, {}).occlusion.empty());
}

TEST(Bake, SettingsAndColourMapsAreValidated) {
  BakeSettings s;
  s.rays = 0;
  EXPECT_THROW(validate(s), InputError);
  s.rays = 8;
  s.max_distance = -1.0;
  EXPECT_THROW(validate(s), InputError);
  s.max_distance = std::nan("");
  EXPECT_THROW(validate(s), InputError);
  s.max_distance.reset();
  s.max_distance_relative = 0.0;
  EXPECT_THROW(validate(s), InputError);
  EXPECT_THROW(validate(ColorMap{-0.1, 1.0, {1, 1, 1}}), InputError);
  EXPECT_THROW(validate(ColorMap{0.0, 1.5, {1, 1, 1}}), InputError);
  EXPECT_THROW(validate(ColorMap{0.8, 0.2, {1, 1, 1}}), InputError);
  EXPECT_THROW(validate(ColorMap{0.0, 1.0, {2, 1, 1}}), InputError);
  EXPECT_NO_THROW(validate(ColorMap{0.5, 1.0, {1, 0.2, 0.1}}));
}

// translucency = lerp(min, max, occlusion) * tint: thin (occlusion 1) gets max.
TEST(Bake, TranslucencyIsALerpFromMinToMaxTimesTint) {
  const ColorMap map{0.5, 1.0, {1.0, 0.2, 0.1}};
  auto expect_rgb = [](const glm::dvec3& got, const glm::dvec3& want) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], want[c], 1e-15) << c;
  };
  expect_rgb(translucency(0.0, map), {0.5, 0.1, 0.05});
  expect_rgb(translucency(1.0, map), {1.0, 0.2, 0.1});
  expect_rgb(translucency(0.5, map), {0.75, 0.15, 0.075});
  expect_rgb(translucency(0.5, ColorMap{}), {0.5, 0.5, 0.5});
}

// ---------------------------------------------------------------------------------------------
// OpenMesh level: smoothing and the colour attribute.

TEST(Bake, SmoothingAveragesOverOneRingNeighbours) {
  const PolyMesh m = meshgen::icosphere(1.0, 2);
  std::vector<double> v(m.n_vertices(), 0.25);
  smooth(m, v, 3);
  for (double x : v) EXPECT_DOUBLE_EQ(x, 0.25);  // a constant is a fixed point

  std::fill(v.begin(), v.end(), 0.0);
  v[0] = 1.0;  // vertex 0 of an icosphere has valence 5
  smooth(m, v, 1);
  EXPECT_DOUBLE_EQ(v[0], 1.0 / 6.0);
  int touched = 0;
  for (std::size_t i = 1; i < v.size(); ++i) touched += v[i] > 0.0;
  EXPECT_EQ(touched, 5);

  // meshgen's box splits corners and edges: copies at one position must stay equal.
  const PolyMesh box_mesh = meshgen::box({1.0, 1.0, 1.0}, 2);
  const Surface b = surface_of(box_mesh);
  std::vector<double> w(b.positions.size());
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = b.positions[i].x > 0.5 ? 1.0 : 0.0;
  smooth(box_mesh, w, 2);
  for (std::size_t i = 0; i < w.size(); ++i) {
    for (std::size_t j = i + 1; j < w.size(); ++j) {
      if (b.positions[i] == b.positions[j]) EXPECT_EQ(w[i], w[j]) << i << " " << j;
    }
  }
}

TEST(Bake, BakeMeshWritesTheMappedColoursAndNothingElse) {
  PolyMesh m = meshgen::box({1.0, 1.0, 0.05}, 4);
  const Surface slab = surface_of(m);
  BakeSettings settings;
  settings.rays = 64;
  settings.max_distance = 0.5;
  const ColorMap map{0.5, 1.0, {1.0, 0.2, 0.1}};
  const MeshBakeReport report = bake_mesh(m, settings, map, 0);
  EXPECT_EQ(report.edges.boundary_edges, 0u);
  const BakeResult direct = bake_surface(slab, settings);
  ASSERT_EQ(report.result.occlusion, direct.occlusion);
  for (auto vh : m.vertices()) {
    const std::size_t i = static_cast<std::size_t>(vh.idx());
    const glm::dvec3 want = translucency(direct.occlusion[i], map);
    const auto c = m.color(vh);
    EXPECT_FLOAT_EQ(c[0], float(want.x));
    EXPECT_FLOAT_EQ(c[1], float(want.y));
    EXPECT_FLOAT_EQ(c[2], float(want.z));
    const auto p = m.point(vh);
    EXPECT_EQ(glm::dvec3(p[0], p[1], p[2]), slab.positions[i]);
  }
}

// ---------------------------------------------------------------------------------------------
// The command (cli.md): files in, files out, exit codes.

std::string ply_text(const Surface& s, bool with_normals = true) {
  std::ostringstream out;
  out.precision(17);
  out << "ply\nformat ascii 1.0\nelement vertex " << s.positions.size()
      << "\nproperty double x\nproperty double y\nproperty double z\n";
  if (with_normals) out << "property double nx\nproperty double ny\nproperty double nz\n";
  out << "element face " << s.triangles.size() << "\nproperty list uchar int vertex_indices\n"
      << "end_header\n";
  for (std::size_t i = 0; i < s.positions.size(); ++i) {
    const auto& p = s.positions[i];
    out << p.x << " " << p.y << " " << p.z;
    if (with_normals)
      out << " " << s.normals[i].x << " " << s.normals[i].y << " " << s.normals[i].z;
    out << "\n";
  }
  for (const auto& t : s.triangles) out << "3 " << t.x << " " << t.y << " " << t.z << "\n";
  return out.str();
}

class BakeCommand : public ::testing::Test {
 protected:
  void SetUp() override { test::write_file(dir_ / "sphere.ply", ply_text(icosphere(1.0, 3))); }
  std::string in() const { return (dir_ / "sphere.ply").string(); }
  std::string out() const { return (dir_ / "out.ply").string(); }
  // Bad input: exit 2, one line "ltrender: error: ...", and no output file.
  void expect_rejected(const std::string& args) {
    const test::RunResult r = test::run_ltrender("bake " + args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(r.err.rfind("ltrender: error: ", 0), 0u) << args << "\n" << r.err;
    EXPECT_EQ(test::count_lines(r.err), 1) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(out())) << args;
  }
  test::TempDir dir_;
};

TEST_F(BakeCommand, WritesVertexColoursAndKeepsPositionsAndNormals) {
  const test::RunResult r =
      test::run_ltrender("bake " + in() + " -o " + out() + " --rays 32 --min 0.5 --tint 1,0.2,0.1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("Mrays/s"), std::string::npos) << r.out;
  EXPECT_EQ(r.err, "");  // a closed mesh, and stderr is not a terminal: no bar, no warning
  const LoadedMesh before = read_mesh(in());
  const LoadedMesh after = read_mesh(out());
  EXPECT_TRUE(after.read_options.vertex_has_color());
  EXPECT_TRUE(after.read_options.vertex_has_normal());
  ASSERT_EQ(after.mesh.n_vertices(), before.mesh.n_vertices());
  ASSERT_EQ(after.mesh.n_faces(), before.mesh.n_faces());
  for (auto vh : after.mesh.vertices()) {
    EXPECT_EQ(after.mesh.point(vh), before.mesh.point(vh));
    // Normals survive to float precision (the PLY writer stores them as float).
    EXPECT_LT((after.mesh.normal(vh) - before.mesh.normal(vh)).norm(), 1e-7);
    const auto c = after.mesh.color(vh);
    // Red within [0.5, 1] (lerp from --min), green and blue the tint's share of it, 8-bit.
    EXPECT_GE(c[0], 0.5f - 1.0f / 255);
    EXPECT_NEAR(c[1], 0.2f * c[0], 1.0f / 255);
    EXPECT_NEAR(c[2], 0.1f * c[0], 1.0f / 255);
  }
}

TEST_F(BakeCommand, FloatColoursAreWrittenAsFloats) {
  const test::RunResult r =
      test::run_ltrender("bake " + in() + " -o " + out() + " --rays 16 --float-colors");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = test::read_file(out());
  const std::string header = text.substr(0, text.find("end_header"));
  EXPECT_NE(header.find("float red"), std::string::npos) << header;
}

TEST_F(BakeCommand, SameSeedOnOneAndTwoThreadsGivesIdenticalFiles) {
  const std::string out2 = (dir_ / "out2.ply").string();
  const std::string common = " --rays 64 --seed 99 --sampler random --float-colors";
  ASSERT_EQ(test::run_ltrender("bake " + in() + " -o " + out() + common + " --threads 1").exit_code,
            0);
  ASSERT_EQ(test::run_ltrender("bake " + in() + " -o " + out2 + common + " --threads 2").exit_code,
            0);
  const std::string a = test::read_file(out()), b = test::read_file(out2);
  EXPECT_FALSE(a.empty());
  EXPECT_TRUE(a == b);
}

TEST_F(BakeCommand, OpenMeshBakesWithAWarningCountingItsBoundaryEdges) {
  Surface s = box({1.0, 1.0, 1.0}, 4);
  s.triangles.resize(s.triangles.size() - 32);  // one face missing
  test::write_file(dir_ / "open.ply", ply_text(s));
  const test::RunResult r =
      test::run_ltrender("bake " + (dir_ / "open.ply").string() + " -o " + out() + " --rays 16");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("ltrender: warning: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("16 boundary edges"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::exists(out()));
}

TEST_F(BakeCommand, MissingInputIsRejected) {
  expect_rejected((dir_ / "nope.ply").string() + " -o " + out());
}

TEST_F(BakeCommand, NanCoordinatesAreRejected) {
  Surface s = icosphere(1.0, 1);
  std::string text = ply_text(s, false);
  const std::size_t body = text.find("end_header\n") + 11;
  text.replace(body, text.find(' ', body) - body, "nan");
  test::write_file(dir_ / "nan.ply", text);
  expect_rejected((dir_ / "nan.ply").string() + " -o " + out());
}

TEST_F(BakeCommand, EmptyMeshIsRejected) {
  test::write_file(dir_ / "empty.ply",
                   "ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
                   "property float z\nelement face 0\nproperty list uchar int vertex_indices\n"
                   "end_header\n");
  expect_rejected((dir_ / "empty.ply").string() + " -o " + out());
}

TEST_F(BakeCommand, OutputEqualToTheInputIsRejectedAndTheInputKept) {
  const std::string before = test::read_file(in());
  const test::RunResult r = test::run_ltrender("bake " + in() + " -o " + in());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_EQ(test::read_file(in()), before);
}

// Blender writes "Created by Blender3D ..." without `comment`; common readers take it as a
// comment, and so do we, with one warning line.
TEST_F(BakeCommand, UnknownHeaderLinesAreCommentsWithOneWarning) {
  std::string text = ply_text(icosphere(1.0, 3));
  const std::string line = "Created by Blender3D 2.79 - www.blender.org, source file: ''";
  text.insert(text.find("element"), line + "\n");
  test::write_file(dir_ / "blender.ply", text);
  const std::string file = (dir_ / "blender.ply").string();
  const test::RunResult r = test::run_ltrender("bake " + file + " -o " + out() + " --rays 8");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "ltrender: warning: " + file + ": header line 3 '" + line +
                       "' is not a PLY keyword: read as a comment\n");
  EXPECT_EQ(read_mesh(out()).mesh.n_vertices(), read_mesh(in()).mesh.n_vertices());
}

TEST_F(BakeCommand, BadOptionValuesAreRejected) {
  const std::string base = in() + " -o " + out();
  expect_rejected(base + " --rays -5");
  expect_rejected(base + " --rays 0");
  expect_rejected(base + " --min -0.1");
  expect_rejected(base + " --max 1.5");
  expect_rejected(base + " --min 0.9 --max 0.2");
  expect_rejected(base + " --tint 1,0.5");
  expect_rejected(base + " --tint 2,0,0");
  expect_rejected(base + " --max-distance 0");
  expect_rejected(base + " --max-distance 1 --max-distance-relative 0.1");
  expect_rejected(base + " --distribution gaussian");
  expect_rejected(base + " --threads -1");
  expect_rejected(in() + " -o " + (dir_ / "out.obj").string());
  expect_rejected(in() + " -o " + (dir_ / "no_such_dir" / "out.ply").string());
}

}  // namespace
}  // namespace lt::bake

namespace lt {
namespace {

// The baked demo meshes in meshes/ are what scripts/bake_demo_meshes.sh makes: rerunning the
// same command line gives the same bytes, so the committed files cannot drift from the baker.
TEST(BakeDemoMeshes, CommittedFilesMatchTheirCommand) {
  test::TempDir dir;
  const fs::path src = test::source_dir() / "meshes";
  const auto out = dir / "blob_baked.ply";
  const auto r = test::run_ltrender("bake " + (src / "blob.ply").string() + " -o " + out.string() +
                                    " --min 0.1 --max 1 --seed 1");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto bytes = [](const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_TRUE(bytes(out) == bytes(src / "blob_baked.ply"))
      << "meshes/blob_baked.ply differs from a fresh bake: run scripts/bake_demo_meshes.sh";
}

}  // namespace
}  // namespace lt

namespace lt {
namespace {

// bake's contract keeps "everything else the input had": a PLY's texture coordinates and any
// other vertex property come out with their names, types and values (issue 15: u, v vanished).
TEST(BakeKeepsProperties, UvAndOtherVertexPropertiesGoThroughUnchanged) {
  test::TempDir dir;
  // A tetrahedron with u, v (float), a uchar quality and an int id per vertex.
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
      "property float z\nproperty float u\nproperty float v\nproperty uchar quality\n"
      "property int id\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string body =
      "0 0 1 0.125 0.875 7 -3\n1 0 -1 0.25 0.5 255 100000\n-1 0 -1 0.3333333 0.1 0 0\n"
      "0 1.5 0 1 0 42 2147483647\n3 0 1 2\n3 0 3 1\n3 1 3 2\n3 2 3 0\n";
  test::write_file(dir / "in.ply", header + body);
  const auto r = test::run_ltrender("bake " + (dir / "in.ply").string() + " --rays 8 -o " +
                                    (dir / "out.ply").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const LoadedMesh in = read_mesh(dir / "in.ply");
  const LoadedMesh out = read_mesh(dir / "out.ply");
  // u, v are the mesh's texture coordinates (issue 13), written back as float u, v.
  EXPECT_TRUE(out.read_options.vertex_has_texcoord());
  EXPECT_EQ(to_triangle_mesh(out).uvs, to_triangle_mesh(in).uvs);
  EXPECT_EQ(to_triangle_mesh(in).uvs[2], glm::dvec2(0.3333333f, 0.1f));
  EXPECT_NE(test::read_file(dir / "out.ply").find("property float u\nproperty float v\n"),
            std::string::npos);
  ASSERT_EQ(out.extra_vertex_properties.size(), 2u);
  const char* names[] = {"quality", "id"};
  const char* types[] = {"uchar", "int"};
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(out.extra_vertex_properties[k].name, names[k]);
    EXPECT_EQ(out.extra_vertex_properties[k].ply_type, types[k]);
    // Float values read back bit-exact (9 significant digits), integers exactly.
    EXPECT_EQ(out.extra_vertex_properties[k].values, in.extra_vertex_properties[k].values)
        << names[k];
  }
  EXPECT_EQ(in.extra_vertex_properties[1].values[3], 2147483647.0);
  EXPECT_TRUE(out.read_options.vertex_has_color());  // and the bake's own colours
}

TEST(BakeKeepsProperties, BinaryPlyKeepsThemToo) {
  test::TempDir dir;
  PolyMesh mesh = meshgen::icosphere(1.0, 1);
  ExtraVertexProperty u{"s", "double", {}}, flag{"flag", "int8", {}};
  for (auto vh : mesh.vertices()) {
    u.values.push_back(0.1 * vh.idx() + 1e-9);
    flag.values.push_back(vh.idx() % 2 ? -128 : 127);
  }
  write_mesh(dir / "in.ply", mesh,
             OpenMesh::IO::Options::Binary | OpenMesh::IO::Options::VertexNormal, {u, flag});
  const auto r = test::run_ltrender("bake " + (dir / "in.ply").string() + " --rays 8 -o " +
                                    (dir / "out.ply").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const LoadedMesh out = read_mesh(dir / "out.ply");
  EXPECT_TRUE(out.read_options.is_binary());
  ASSERT_EQ(out.extra_vertex_properties.size(), 2u);
  EXPECT_EQ(out.extra_vertex_properties[0].values, u.values);
  EXPECT_EQ(out.extra_vertex_properties[1].values, flag.values);
}

TEST(BakeKeepsProperties, OnlyPlyCanCarryThem) {
  test::TempDir dir;
  const PolyMesh mesh = meshgen::icosphere(1.0, 1);
  ExtraVertexProperty u{"u", "float", std::vector<double>(mesh.n_vertices(), 0.5)};
  try {
    write_mesh(dir / "m.obj", mesh, OpenMesh::IO::Options(), {u});
    FAIL() << "an OBJ cannot hold u";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("only PLY can carry the vertex properties u"),
              std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "m.obj"));
}

}  // namespace
}  // namespace lt
