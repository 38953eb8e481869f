// The rays of the thickness bake, shared by the vertex baker (thickness_baker.h) and the
// UV-space baker (uv_baker.h): from a point on the surface, rays over the hemisphere around the
// flipped normal, up to the max distance D, through Embree; the fraction that hits (or the mean
// hit distance, see Estimator) is the point's occlusion. Random numbers are counter-based
// (seed, point, ray), so a point's result depends on nothing but its own seed.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "bake/bake_settings.h"

namespace lt::bake {

// One point to measure: rays start at `position` pushed inward by epsilon.
struct RayOrigin {
  glm::dvec3 position;
  glm::dvec3 inward;  // unit: the flipped normal
  std::uint64_t
      seed;  // its random numbers' index (the vertex bake: a vertex; the UV bake: a texel)
};

class OcclusionTracer {
 public:
  // The surface the rays hit. D = settings.max_distance, or max_distance_relative times the
  // diagonal of the positions' bounding box; the origin offset and tnear are kRayEpsilonRelative
  // times the diagonal. Positions must be finite; the BVH is built by the first trace().
  OcclusionTracer(const std::vector<glm::dvec3>& positions,
                  const std::vector<glm::uvec3>& triangles, const BakeSettings& settings);
  ~OcclusionTracer();
  OcclusionTracer(const OcclusionTracer&) = delete;
  OcclusionTracer& operator=(const OcclusionTracer&) = delete;

  double max_distance() const;
  double epsilon() const;
  int threads() const;           // settings.threads, or the hardware's
  double build_seconds() const;  // the Embree BVH
  double trace_seconds() const;  // all trace() calls
  // False when nothing can be hit (all positions at one point, or D not beyond the origin
  // offset): trace() then casts no ray.
  bool casts_rays() const;

  // Occlusion in [0, 1] per origin. Threads take chunks of origins from a shared counter and
  // write each result to its own slot, so the result is the same whatever the thread count.
  // Without casts_rays() every origin gets 0. `progress` runs on the calling thread.
  std::vector<double> trace(const std::vector<RayOrigin>& origins, const Progress& progress = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lt::bake
