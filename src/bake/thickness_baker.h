// Thickness baker: the GDC 2011 talk's "local thickness", i.e. ambient occlusion computed with
// the normals flipped, stored per vertex (the talk's Wii variant, "Computing Local Thickness").
//
// From every vertex, rays go into the interior, over the hemisphere around the flipped normal,
// up to a max distance D. A ray that hits the surface within D means a wall of the object is
// close behind this point: the object is thin there. So:
//
//   occlusion     = fraction of the rays that hit within D            (1 = thin, 0 = thick)
//   translucency  = lerp(min, max, occlusion) * tint                  (thin parts are bright)
//
// This is the addendum's 3ds Max recipe, Dark and Bright swapped from Max's defaults: an occluded
// ray (Max's "Dark") gets the maximum translucency (`max`, white by default) and an unoccluded one
// (Max's "Bright") the minimum (`min`; the addendum used 50% grey, i.e. `min = 0.5`).
//
// The core works on plain arrays (bake_occlusion) so that it can be tested without files; the
// mesh-level functions below add OpenMesh smoothing and the colour attribute.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "bake/bake_settings.h"
#include "mesh/poly_mesh.h"

namespace lt::bake {

struct BakeResult {
  std::vector<double> occlusion;            // per vertex, in [0, 1], 1 = thin (see Estimator)
  double max_distance = 0.0;                // D actually used, scene units
  double epsilon = 0.0;                     // origin offset and tnear, scene units
  std::uint64_t rays_traced = 0;            // rays per vertex x distinct positions baked
  std::size_t vertices_without_normal = 0;  // baked as occlusion 0, no rays
  int threads = 1;
  double build_seconds = 0.0;  // Embree BVH
  double trace_seconds = 0.0;
};

// A normal with a direction, which both bakers bake along: non-zero and finite (it need not be
// unit length).
inline bool usable_normal(const glm::dvec3& normal) {
  const double len = glm::length(normal);
  return std::isfinite(len) && len > 0.0;
}

// The core. Vertices at bit-identical positions (split for hard edges or seams) are baked once,
// together, with the mean of their unit normals, seeded by their lowest vertex index; `normals`
// need not be unit length. Where no copy has a usable (non-zero, finite) normal, the
// area-weighted normal of the faces around the position is used (orientation from the winding);
// a position with neither (no face with area, or normals that cancel as on a double-sided sheet)
// gets occlusion 0 and casts no rays (counted in vertices_without_normal).
// Degenerate triangles are fine (Embree skips them). Rays that leave through a hole in an open
// mesh find nothing and count as unoccluded (at distance D for the distance estimator).
BakeResult bake_occlusion(const std::vector<glm::dvec3>& positions,
                          const std::vector<glm::dvec3>& normals,
                          const std::vector<glm::uvec3>& triangles, const BakeSettings& settings,
                          const Progress& progress = {});

// Open and non-manifold edges, counted after welding vertices with identical positions (so a
// mesh with split normals at its creases, or the duplicated vertices OpenMesh's importer makes
// for non-manifold faces, is not reported as open). Internal fan diagonals are shared by two
// triangles and so never counted; triangles with two corners at one position are skipped.
struct EdgeReport {
  std::size_t boundary_edges = 0;      // used by one triangle: a hole or an open border
  std::size_t non_manifold_edges = 0;  // used by three or more triangles
};
EdgeReport count_problem_edges(const std::vector<glm::dvec3>& positions,
                               const std::vector<glm::uvec3>& triangles);

// The mesh's vertices, normals and faces (fan-triangulated) as arrays, vertex i = handle i.
struct Surface {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;  // zero where the mesh has none
  std::vector<glm::uvec3> triangles;
};
Surface surface_of(const PolyMesh& mesh);

// `iterations` Jacobi steps of value <- (value + sum of neighbours) / (1 + neighbour count),
// neighbours from OpenMesh's vertex-vertex circulator. Like the bake, it works per position:
// copies of a vertex split at a hard edge are merged (their one-rings united) and stay equal.
// Isolated vertices keep their value.
void smooth(const PolyMesh& mesh, std::vector<double>& values, int iterations);

// lerp(min, max, occlusion) * tint, clamped to [0, 1].
glm::dvec3 translucency(double occlusion, const ColorMap& map);

// What bake_mesh did, for the command's report and warnings.
struct MeshBakeReport {
  BakeResult result;
  EdgeReport edges;
};

// Bakes, smooths `smooth_iterations` times, and writes the translucency into the mesh's vertex
// colours. Nothing else in the mesh changes.
MeshBakeReport bake_mesh(PolyMesh& mesh, const BakeSettings& settings, const ColorMap& map,
                         int smooth_iterations, const Progress& progress = {});

}  // namespace lt::bake
