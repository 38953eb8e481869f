#include "paths/arbfp/arb_guards.h"

#include <algorithm>
#include <limits>

#include "arb/arb_ir.h"
#include "model/translucency.h"

namespace lt::arbfp {

namespace {

// An interpolated normal at least this long is normalised in float without any guard case: far
// above kMinNormalLength (1e-6), and its squared length far above float's smallest normal.
constexpr double kNormalMargin = 1e-3;

// A light this far from the bounds (relative to their diagonal, and to the camera-relative
// magnitudes float rounds at) keeps dist^2 > 0 in the fragment program's float arithmetic.
constexpr double kBoundsMargin = 1e-3;
constexpr double kFloatMargin = 1e-5;

double distance_to_box(const glm::dvec3& p, const MaterialSurfaces& b) {
  const glm::dvec3 outside = glm::max(glm::max(b.lo - p, p - b.hi), glm::dvec3(0));
  return glm::length(outside);
}

}  // namespace

// The closest point of the triangle to the origin by its Voronoi regions (vertex, edge, face),
// as in Ericson, Real-Time Collision Detection 5.1.5.
double distance_to_origin(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = -a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return glm::length(a);
  const glm::dvec3 bp = -b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return glm::length(b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return glm::length(a + ab * (d1 / (d1 - d3)));
  const glm::dvec3 cp = -c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return glm::length(c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return glm::length(a + ac * (d2 / (d2 - d6)));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    return glm::length(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  }
  const double denom = va + vb + vc;
  if (denom == 0) {
    // A degenerate triangle (collinear normals): the closest of its three edges' points.
    double best = std::min({glm::length(a), glm::length(b), glm::length(c)});
    for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{a, c}}) {
      const glm::dvec3 e = q - p;
      const double l2 = glm::dot(e, e);
      if (l2 > 0)
        best = std::min(best, glm::length(p + e * std::clamp(-glm::dot(p, e) / l2, 0.0, 1.0)));
    }
    return best;
  }
  return glm::length(a + ab * (vb / denom) + ac * (vc / denom));
}

MaterialSurfaces material_surfaces(const Scene& scene, const Material& material) {
  MaterialSurfaces s;
  for (const SceneObject& o : scene.objects) {
    if (scene.materials[static_cast<size_t>(o.material)].name != material.name) continue;
    for (const glm::dvec3& p : o.mesh.positions) {
      s.lo = glm::min(s.lo, p);
      s.hi = glm::max(s.hi, p);
    }
    const auto& nr = o.mesh.normals;
    for (const glm::uvec3& t : o.mesh.triangles) {
      s.shortest_normal =
          std::min(s.shortest_normal, distance_to_origin(nr[t.x], nr[t.y], nr[t.z]));
    }
  }
  return s;
}

GuardNeeds guard_needs(const Scene& scene, const MaterialSurfaces& surfaces, bool all,
                       const LightNumbers& numbers) {
  GuardNeeds g;
  const size_t n = scene.lights.size();
  g.distance_zero.assign(n, false);
  g.attenuation_floor.assign(n, false);
  for (size_t i = 0; i < n; ++i) {
    const bool point = scene.lights[i].type == Light::Type::Point;
    g.distance_zero[i] = g.attenuation_floor[i] = point;
  }
  if (all) return g;
  if (surfaces.empty()) return g;
  if (surfaces.shortest_normal > kNormalMargin) {
    g.zero_normal = false;
    g.notes.push_back("zero-normal guard dropped: no interpolated normal is shorter than " +
                      ir::num(surfaces.shortest_normal) +
                      " (the origin is outside every triangle of "
                      "vertex normals)");
  }
  const double diagonal = glm::length(surfaces.hi - surfaces.lo);
  for (size_t i = 0; i < n; ++i) {
    const Light& l = scene.lights[i];
    if (l.type != Light::Type::Point) continue;
    const double d = distance_to_box(l.position, surfaces);
    const double magnitude = std::max({glm::length(surfaces.lo - scene.camera.eye),
                                       glm::length(surfaces.hi - scene.camera.eye),
                                       glm::length(l.position - scene.camera.eye)});
    const std::string light = "light " + std::to_string(light_number(numbers, i)) + ": ";
    if (d > std::max(kBoundsMargin * diagonal, kFloatMargin * magnitude)) {
      g.distance_zero[i] = false;
      g.notes.push_back(light + "distance-0 guard dropped: the light is " + ir::num(d) +
                        " from the mesh bounds");
    }
    // kc + kl d + kq d^2 grows with d: its least value over the surfaces is at the bounds.
    const double least = l.kc + (g.distance_zero[i] ? 0 : l.kl * d + l.kq * d * d);
    if (least >= model::kMinAttenuationDenominator) {
      g.attenuation_floor[i] = false;
      g.notes.push_back(light + "attenuation floor dropped: kc + kl d + kq d^2 >= " +
                        ir::num(least) + " on every surface");
    }
  }
  return g;
}

}  // namespace lt::arbfp
