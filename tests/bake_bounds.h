// The analytic sphere of the thickness bake, shared by the vertex-bake tests (bake_test.cpp) and
// the UV-bake tests (uv_bake_test.cpp).
//
// On a sphere of radius R, a ray leaving a surface point at angle theta from the inward normal
// travels the chord 2 R cos(theta). It hits within D when cos(theta) < D / 2R =: a. With cosine
// sampling, P(cos(theta) < a) = a^2; with uniform sampling it is a.
//
// The baked sphere is a polyhedron, and rays start eps inside it: the true occlusion is
// sandwiched between two spheres. From a start point at radius rho, with its rays around the
// inward radial direction, the far intersection with a sphere of radius s is within D iff
// cos(theta) <= x*(rho, s) = (D^2 + rho^2 - s^2) / (2 D rho). Every polyhedral chord is at most
// the outer sphere's (s = R) and at least the inscribed sphere's (s = R - sagitta, the smallest
// distance from the centre to a face plane). A vertex starts at rho = R - eps; a point inside a
// face (a texel of the UV bake, whose interpolated normal is radial when the vertex normals are)
// anywhere in [R - sagitta - eps, R - eps]. The expected occlusion lies between the extremes of
// F(x*) over those ranges, F(x) = x^2 (cosine) or x (uniform).
#pragma once

#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <vector>

#include "bake/thickness_baker.h"

namespace lt::bake {

inline double sagitta(const std::vector<glm::dvec3>& positions,
                      const std::vector<glm::uvec3>& triangles, const glm::dvec3& centre,
                      double radius) {
  double inscribed = radius;
  for (const auto& t : triangles) {
    const glm::dvec3 cross =
        glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
    if (glm::length(cross) == 0.0) continue;  // a sliver at a pole has no plane
    const glm::dvec3 n = glm::normalize(cross);
    inscribed = std::min(inscribed, std::abs(glm::dot(n, positions[t.x] - centre)));
  }
  return radius - inscribed;
}

inline double sagitta(const Surface& s, const glm::dvec3& centre, double radius) {
  return sagitta(s.positions, s.triangles, centre, radius);
}

struct Expected {
  double lo, hi;
};

// `start_depth`: how far inside the sphere (beyond eps) a start point may be: 0 for vertices,
// the sagitta for points inside faces.
inline Expected sphere_occlusion(double radius, double d, double eps, double sag, Distribution dist,
                                 double start_depth = 0.0) {
  auto cdf = [&](double rho, double s) {
    const double x = std::clamp((d * d + rho * rho - s * s) / (2.0 * d * rho), 0.0, 1.0);
    return dist == Distribution::Cosine ? x * x : x;
  };
  const double rho_hi = radius - eps, rho_lo = radius - eps - start_depth;
  Expected e{1.0, 0.0};
  for (const double s : {radius, radius - sag}) {
    // x* is monotone in s, and in rho either monotone or convex with its minimum at
    // rho = sqrt(D^2 - s^2): the extremes are at the range's ends or there.
    std::vector<double> rhos = {rho_lo, rho_hi};
    const double critical = d * d - s * s > 0 ? std::sqrt(d * d - s * s) : -1.0;
    if (critical > rho_lo && critical < rho_hi) rhos.push_back(critical);
    for (const double rho : rhos) {
      e.lo = std::min(e.lo, cdf(rho, s));
      e.hi = std::max(e.hi, cdf(rho, s));
    }
  }
  return e;
}

// Binomial standard deviation of a fraction estimated from `n` independent rays. The stratified
// sampler's variance is lower (its rays are evenly spread), so this bound is conservative there.
inline double binomial_sigma(double p, double n) {
  return std::sqrt(std::max(p * (1.0 - p), 1e-4) / n);
}

// The sphere's exact occlusion, min(1, D/2R)^2 (cosine) or min(1, D/2R) (uniform).
inline double analytic_sphere_occlusion(double radius, double d, Distribution dist) {
  const double a = std::min(1.0, d / (2 * radius));
  return dist == Distribution::Cosine ? a * a : a;
}

}  // namespace lt::bake
