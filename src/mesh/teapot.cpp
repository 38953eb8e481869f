// meshgen::teapot: Newell's Bezier patches (mesh/teapot_data.cpp) evaluated on a grid, each patch
// a chart of one UV atlas.
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "mesh/mesh_builder.h"
#include "mesh/meshgen.h"
#include "mesh/teapot_data.h"
#include "mesh/uv_atlas.h"

namespace lt::meshgen {

namespace {

using ControlNet = std::array<glm::dvec3, 16>;  // row i, column j at 4 * i + j

// The dataset is z up; ltrender's meshes are y up. (x, y, z) -> (x, z, -y) is a rotation, so
// the patches keep their orientation.
ControlNet control_net(int patch) {
  ControlNet net;
  for (int k = 0; k < 16; ++k) {
    const auto& c = kTeapotControlPointData[static_cast<std::size_t>(
        kTeapotPatchIndices[static_cast<std::size_t>(patch)][static_cast<std::size_t>(k)])];
    net[static_cast<std::size_t>(k)] = {c[0], c[2], -c[1]};
  }
  return net;
}

std::array<double, 4> bernstein(double t) {
  const double r = 1.0 - t;
  return {r * r * r, 3.0 * t * r * r, 3.0 * t * t * r, t * t * t};
}

std::array<double, 4> bernstein_derivative(double t) {
  const double r = 1.0 - t;
  return {-3.0 * r * r, 3.0 * r * r - 6.0 * t * r, 6.0 * t * r - 3.0 * t * t, 3.0 * t * t};
}

// sum_i bt[i] * (sum_j bs[j] * net[i][j]), the inner sum first: on a patch edge (s or t equal to
// 0 or 1) every weight but one is exactly 0 and that one exactly 1, so two patches that share an
// edge's control points in the same order compute bit-identical positions along it.
glm::dvec3 combine(const ControlNet& net, const std::array<double, 4>& bs,
                   const std::array<double, 4>& bt) {
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < 4; ++i) {
    glm::dvec3 row(0.0);
    for (std::size_t j = 0; j < 4; ++j) row += bs[j] * net[4 * i + j];
    sum += bt[i] * row;
  }
  return sum;
}

// s runs along a row of the control net (column index j), t across the rows (index i). The
// dataset's patches all have dP/ds x dP/dt pointing out of the teapot.
glm::dvec3 patch_point(const ControlNet& net, double s, double t) {
  return combine(net, bernstein(s), bernstein(t));
}

glm::dvec3 outward_cross(const ControlNet& net, double s, double t) {
  const glm::dvec3 ds = combine(net, bernstein_derivative(s), bernstein(t));
  const glm::dvec3 dt = combine(net, bernstein(s), bernstein_derivative(t));
  const glm::dvec3 n = glm::cross(ds, dt);
  // Where a patch edge collapses to a point, dP/ds vanishes along it: the cross product is
  // rounding noise, not a direction.
  const double scale = glm::length(ds) + glm::length(dt);
  return glm::length(n) > 1e-9 * scale * scale ? n : glm::dvec3(0.0);
}

// The analytic normal; at a collapsed edge, the normal of a sample a little inside the patch
// (the copies at the point are averaged afterwards, which gives the axis there).
glm::dvec3 patch_normal(const ControlNet& net, double s, double t) {
  glm::dvec3 n = outward_cross(net, s, t);
  if (n == glm::dvec3(0.0)) {
    constexpr double kInside = 1e-3;
    auto inward = [&](double x) { return x < 0.5 ? x + kInside : (x > 0.5 ? x - kInside : x); };
    n = outward_cross(net, inward(s), inward(t));
  }
  const double len = glm::length(n);
  return len > 0 ? n / len : glm::dvec3(0.0);
}

// A chart's size: the mean length of the patch's s and t iso-curves, so that a texel covers
// about the same surface on every chart.
glm::dvec2 surface_extent(const ControlNet& net) {
  constexpr int kSteps = 16;
  glm::dvec2 sum(0.0);
  for (int k = 0; k <= 4; ++k) {
    const double fixed = k / 4.0;
    for (int i = 0; i < kSteps; ++i) {
      const double a = static_cast<double>(i) / kSteps, b = static_cast<double>(i + 1) / kSteps;
      sum.x += glm::length(patch_point(net, b, fixed) - patch_point(net, a, fixed));
      sum.y += glm::length(patch_point(net, fixed, b) - patch_point(net, fixed, a));
    }
  }
  return sum / 5.0;
}

// Unites copies of one point made by different patches (bit-identical where two patches share
// an edge in the same direction, within rounding where the directions differ, as between the
// body and the bottom) and gives them the mean of their normals. The patches meet smoothly
// (tangent-continuous) except where the handle's lower end touches the body at one control
// point: copies whose normals differ by more than kCrease keep their own.
void average_coincident_normals(Geometry& g) {
  constexpr double kTolerance = 1e-9;  // the dataset's units: rounding of values near 3
  const double kCrease = std::cos(45.0 * 3.14159265358979323846 / 180.0);
  const std::size_t n = g.positions.size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<std::size_t> by_x(n);
  std::iota(by_x.begin(), by_x.end(), std::size_t{0});
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
    return g.positions[a].x < g.positions[b].x || (g.positions[a].x == g.positions[b].x && a < b);
  });
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      const auto& p = g.positions[by_x[a]];
      const auto& q = g.positions[by_x[b]];
      if (q.x - p.x > kTolerance) break;
      if (glm::length(q - p) <= kTolerance &&
          glm::dot(g.normals[by_x[a]], g.normals[by_x[b]]) > kCrease) {
        parent[find(by_x[a])] = find(by_x[b]);
      }
    }
  }
  std::vector<glm::dvec3> sum(n, glm::dvec3(0.0));
  for (std::size_t v = 0; v < n; ++v) sum[find(v)] += g.normals[v];
  for (std::size_t v = 0; v < n; ++v) {
    const glm::dvec3& s = sum[find(v)];
    const double len = glm::length(s);
    g.normals[v] = len > 0 ? s / len : glm::dvec3(0.0);
  }
}

}  // namespace

PolyMesh teapot(int subdivisions) {
  LT_CHECK(subdivisions >= 1 && subdivisions <= 256, "teapot subdivisions out of range");
  std::vector<ControlNet> nets;
  std::vector<glm::dvec2> extents;
  for (int p = 0; p < kTeapotPatches; ++p) {
    nets.push_back(control_net(p));
    extents.push_back(surface_extent(nets.back()));
  }
  const std::vector<ChartPlacement> charts =
      pack_charts(extents, static_cast<double>(kTeapotGutterTexels) / 1024.0);
  Geometry g;
  const int n = subdivisions;
  for (std::size_t p = 0; p < nets.size(); ++p) {
    const ControlNet& net = nets[p];
    // A boundary row whose four control points coincide is a patch edge collapsed to that point
    // (the knob's top, the bottom's centre). Like a UV sphere's pole it gets one vertex per
    // cell, at the cell's middle s and exactly at the point, so that no triangle is degenerate.
    auto collapsed = [&](int row) {
      const std::size_t r = static_cast<std::size_t>(4 * row);
      return net[r] == net[r + 1] && net[r] == net[r + 2] && net[r] == net[r + 3];
    };
    auto add = [&](double s, double t, const glm::dvec3& position) {
      return g.add(position, patch_normal(net, s, t),
                   charts[p].offset + charts[p].scale * glm::dvec2(s, t));
    };
    std::vector<std::vector<int>> rows(static_cast<std::size_t>(n + 1));
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n;
      auto& row = rows[static_cast<std::size_t>(i)];
      const bool point = (i == 0 && collapsed(0)) || (i == n && collapsed(3));
      for (int j = 0; j < (point ? n : n + 1); ++j) {
        if (point) {
          const double s = (j + 0.5) / n;
          row.push_back(add(s, t, net[i == 0 ? 0 : 12]));
        } else {
          const double s = static_cast<double>(j) / n;
          row.push_back(add(s, t, patch_point(net, s, t)));
        }
      }
    }
    // Counter-clockwise in (s, t), hence in the chart and seen from outside.
    for (int i = 0; i < n; ++i) {
      const auto& lo = rows[static_cast<std::size_t>(i)];
      const auto& hi = rows[static_cast<std::size_t>(i + 1)];
      for (std::size_t j = 0; j < static_cast<std::size_t>(n); ++j) {
        if (lo.size() == static_cast<std::size_t>(n)) {
          g.triangles.push_back({lo[j], hi[j + 1], hi[j]});
        } else if (hi.size() == static_cast<std::size_t>(n)) {
          g.triangles.push_back({lo[j], lo[j + 1], hi[j]});
        } else {
          add_quad(g, lo[j], lo[j + 1], hi[j + 1], hi[j]);
        }
      }
    }
  }
  average_coincident_normals(g);
  return to_mesh(g);
}

}  // namespace lt::meshgen
