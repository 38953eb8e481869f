#include "bake/thickness_baker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>

#include "bake/occlusion_tracer.h"
#include "core/error.h"
#include "mesh/triangulate.h"

namespace lt::bake {

namespace {

// Vertices with bit-identical positions share one id, ids numbered in sorted position order.
// Sorting, not hashing, so that -0.0 and 0.0 weld like they do geometrically.
struct Welding {
  std::vector<std::uint32_t> id;  // per vertex
  std::size_t groups = 0;
};

Welding weld_by_position(const std::vector<glm::dvec3>& positions) {
  const std::size_t nv = positions.size();
  std::vector<std::uint32_t> order(nv);
  for (std::size_t i = 0; i < nv; ++i) order[i] = static_cast<std::uint32_t>(i);
  auto key = [&](std::uint32_t i) {
    return std::tie(positions[i].x, positions[i].y, positions[i].z);
  };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return key(a) < key(b) || (key(a) == key(b) && a < b);
  });
  Welding w;
  w.id.resize(nv);
  std::uint32_t id = 0;
  for (std::size_t k = 0; k < nv; ++k) {
    if (k > 0 && key(order[k]) != key(order[k - 1])) ++id;
    w.id[order[k]] = id;
  }
  w.groups = nv == 0 ? 0 : static_cast<std::size_t>(id) + 1;
  return w;
}

}  // namespace

// ---------------------------------------------------------------------------------------------

BakeResult bake_occlusion(const std::vector<glm::dvec3>& positions,
                          const std::vector<glm::dvec3>& normals,
                          const std::vector<glm::uvec3>& triangles, const BakeSettings& settings,
                          const Progress& progress) {
  validate(settings);
  const std::size_t nv = positions.size();
  LT_CHECK(normals.size() == nv, "one normal per vertex");
  for (const auto& t : triangles) {
    LT_CHECK(t.x < nv && t.y < nv && t.z < nv, "triangle index out of range");
  }

  BakeResult result;
  result.occlusion.assign(nv, 0.0);
  OcclusionTracer tracer(positions, triangles, settings);
  result.threads = tracer.threads();
  result.epsilon = tracer.epsilon();
  result.max_distance = tracer.max_distance();
  if (nv == 0) return result;

  // Ray normals, one per position. Vertices at the same position (split for hard edges or
  // texture seams) cast their rays together, with the mean of their unit normals: at a box corner
  // split three ways the rays go along the inward diagonal, so the origin is inside the solid
  // (an origin pushed along one face's normal would sit on the two other faces' planes and see
  // half its rays leave at once), and every copy of the corner gets the same thickness.
  const Welding weld = weld_by_position(positions);
  const std::size_t ng = weld.groups;
  std::vector<std::uint32_t> representative(ng, std::numeric_limits<std::uint32_t>::max());
  std::vector<glm::dvec3> normal_sum(ng, glm::dvec3(0.0));
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t g = weld.id[v];
    representative[g] = std::min(representative[g], static_cast<std::uint32_t>(v));
    if (usable_normal(normals[v])) normal_sum[g] += glm::normalize(normals[v]);
  }
  // Fallback where no copy has a usable normal: the area-weighted normal of the faces around the
  // position (a cross product's length is twice its triangle's area).
  bool any_missing = false;
  for (const auto& n : normal_sum) any_missing = any_missing || !usable_normal(n);
  if (any_missing) {
    std::vector<glm::dvec3> face_sum(ng, glm::dvec3(0.0));
    for (const auto& t : triangles) {
      const glm::dvec3 n =
          glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
      if (!usable_normal(n)) continue;
      for (const unsigned v : {t.x, t.y, t.z}) face_sum[weld.id[v]] += n;
    }
    for (std::size_t g = 0; g < ng; ++g) {
      if (!usable_normal(normal_sum[g])) normal_sum[g] = face_sum[g];
    }
  }
  // The positions to trace, in the order of their first vertex, each seeded by that vertex's
  // index. A position whose normals cancel (a double-sided sheet) or that touches no face with
  // area has no inside: occlusion 0.
  std::vector<std::uint32_t> tasks;
  std::vector<RayOrigin> origins;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t g = weld.id[v];
    if (!usable_normal(normal_sum[g])) {
      ++result.vertices_without_normal;
    } else if (representative[g] == v) {
      tasks.push_back(g);
      origins.push_back({positions[v], -glm::normalize(normal_sum[g]), v});
    }
  }
  const std::vector<double> traced = tracer.trace(origins, progress);
  result.build_seconds = tracer.build_seconds();
  result.trace_seconds = tracer.trace_seconds();
  std::vector<double> occlusion(ng, 0.0);
  for (std::size_t k = 0; k < tasks.size(); ++k) occlusion[tasks[k]] = traced[k];
  for (std::size_t v = 0; v < nv; ++v) result.occlusion[v] = occlusion[weld.id[v]];
  if (tracer.casts_rays()) {
    result.rays_traced =
        static_cast<std::uint64_t>(tasks.size()) * static_cast<std::uint64_t>(settings.rays);
  }
  return result;
}

EdgeReport count_problem_edges(const std::vector<glm::dvec3>& positions,
                               const std::vector<glm::uvec3>& triangles) {
  const std::vector<std::uint32_t> weld = weld_by_position(positions).id;
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * triangles.size());
  for (const auto& t : triangles) {
    const std::uint32_t c[3] = {weld[t.x], weld[t.y], weld[t.z]};
    // A triangle with two corners at one position is a collapsed sliver, not part of the surface:
    // counting it would make its long edge look used three or four times.
    if (c[0] == c[1] || c[1] == c[2] || c[2] == c[0]) continue;
    for (int e = 0; e < 3; ++e) {
      std::uint32_t a = c[e], b = c[(e + 1) % 3];
      if (a > b) std::swap(a, b);
      edges.push_back((static_cast<std::uint64_t>(a) << 32) | b);
    }
  }
  std::sort(edges.begin(), edges.end());
  EdgeReport report;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const std::size_t uses = j - i;
    if (uses == 1) ++report.boundary_edges;
    if (uses > 2) ++report.non_manifold_edges;
    i = j;
  }
  return report;
}

Surface surface_of(const PolyMesh& mesh) {
  Surface s;
  s.positions.reserve(mesh.n_vertices());
  s.normals.reserve(mesh.n_vertices());
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    s.positions.emplace_back(p[0], p[1], p[2]);
    if (mesh.has_vertex_normals()) {
      const auto& n = mesh.normal(vh);
      s.normals.emplace_back(n[0], n[1], n[2]);
    } else {
      s.normals.emplace_back(0.0);
    }
  }
  // The renderer's triangles: vertex indices are OpenMesh's vertex handles.
  s.triangles = triangulate_faces(mesh);
  return s;
}

void smooth(const PolyMesh& mesh, std::vector<double>& values, int iterations) {
  LT_CHECK(values.size() == mesh.n_vertices(), "one value per vertex");
  if (iterations <= 0 || values.empty()) return;
  // Smooth per position, like the bake: copies of a vertex split at a hard edge share one value
  // and the union of their one-rings, so smoothing cannot open a seam between them.
  std::vector<glm::dvec3> positions;
  positions.reserve(mesh.n_vertices());
  for (auto vh : mesh.vertices()) {
    const auto& p = mesh.point(vh);
    positions.emplace_back(p[0], p[1], p[2]);
  }
  const Welding weld = weld_by_position(positions);
  const std::size_t ng = weld.groups;

  std::vector<double> value(ng, 0.0);
  std::vector<int> copies(ng, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links;  // (group, neighbour group)
  for (auto vh : mesh.vertices()) {
    const std::uint32_t g = weld.id[static_cast<std::size_t>(vh.idx())];
    value[g] += values[static_cast<std::size_t>(vh.idx())];
    ++copies[g];
    for (auto nh : mesh.vv_range(vh)) {
      const std::uint32_t h = weld.id[static_cast<std::size_t>(nh.idx())];
      if (h != g) links.emplace_back(g, h);
    }
  }
  for (std::size_t g = 0; g < ng; ++g) value[g] /= copies[g];
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  std::vector<std::size_t> first(ng + 1, 0);  // links of group g: [first[g], first[g + 1])
  for (const auto& l : links) ++first[l.first + 1];
  for (std::size_t g = 0; g < ng; ++g) first[g + 1] += first[g];

  // Jacobi steps: every new value from the previous iteration's values only, so the result does
  // not depend on the vertex order.
  std::vector<double> next(ng);
  for (int it = 0; it < iterations; ++it) {
    for (std::size_t g = 0; g < ng; ++g) {
      double sum = value[g];
      for (std::size_t k = first[g]; k < first[g + 1]; ++k) sum += value[links[k].second];
      next[g] = sum / static_cast<double>(1 + first[g + 1] - first[g]);
    }
    value.swap(next);
  }
  for (std::size_t v = 0; v < values.size(); ++v) values[v] = value[weld.id[v]];
}

glm::dvec3 translucency(double occlusion, const ColorMap& map) {
  const double t = map.min + (map.max - map.min) * std::clamp(occlusion, 0.0, 1.0);
  return glm::clamp(t * map.tint, glm::dvec3(0.0), glm::dvec3(1.0));
}

MeshBakeReport bake_mesh(PolyMesh& mesh, const BakeSettings& settings, const ColorMap& map,
                         int smooth_iterations, const Progress& progress) {
  validate(map);
  if (smooth_iterations < 0) throw InputError("--smooth", "", "must be >= 0");
  const Surface surface = surface_of(mesh);
  MeshBakeReport report;
  report.edges = count_problem_edges(surface.positions, surface.triangles);
  report.result =
      bake_occlusion(surface.positions, surface.normals, surface.triangles, settings, progress);
  smooth(mesh, report.result.occlusion, smooth_iterations);
  if (!mesh.has_vertex_colors()) mesh.request_vertex_colors();
  for (auto vh : mesh.vertices()) {
    const glm::dvec3 c =
        translucency(report.result.occlusion[static_cast<std::size_t>(vh.idx())], map);
    mesh.set_color(vh, PolyMesh::Color(static_cast<float>(c.x), static_cast<float>(c.y),
                                       static_cast<float>(c.z)));
  }
  return report;
}

}  // namespace lt::bake
