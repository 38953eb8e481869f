// What a thickness bake is asked for, shared by the vertex baker (thickness_baker.h), the
// UV-space baker (uv_baker.h) and the ray code both use (occlusion_tracer.h): the ray settings,
// the colour map, their validation, the progress callback.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <glm/glm.hpp>
#include <optional>

namespace lt::bake {

// How ray directions are spread over the hemisphere around the flipped normal.
enum class Distribution {
  Cosine,   // pdf cos(theta)/pi: what AO bakers use; the chord test gives occlusion (D/2R)^2
  Uniform,  // pdf 1/(2 pi): every direction counts the same; occlusion D/2R on a sphere
};

// What a vertex's rays are turned into.
enum class Estimator {
  Occlusion,  // fraction of rays hitting within D (classic AO, the addendum's recipe)
  Distance,   // 1 - mean(min(hit distance, D)) / D, escaped rays counting as D (Meshmixer, Maya)
};

// How the N (u1, u2) points of one vertex are chosen. With both, each single ray follows the
// chosen Distribution exactly (so both are unbiased); they differ in how evenly the N rays of
// one vertex cover the hemisphere.
enum class Sampler {
  // Hammersley points ((i + 0.5) / N, radical inverse of i) shifted by a per-vertex random
  // offset modulo 1 (Cranley-Patterson rotation): noise falls faster than 1/sqrt(N).
  Stratified,
  // Independent uniform points: plain Monte Carlo, binomial noise sqrt(p(1-p)/N).
  Random,
};

// The default max distance, as a fraction of the bounding-box diagonal. A quarter of the
// diagonal is about half the diameter of a sphere (diagonal = 2 sqrt(3) R, so D = 0.87 R and a
// sphere bakes to occlusion (D/2R)^2 = 0.19 with cosine rays): walls closer than that read as
// thin, the bulk of a roughly convex object reads as thick. The addendum's advice applies:
// "If you have a big object, make it bigger. The opposite for a small object."
inline constexpr double kDefaultMaxDistanceRelative = 0.25;

// Ray origins are offset along the flipped normal by this fraction of the bounding-box diagonal,
// and hits closer than the same distance are ignored (Embree's tnear). Positions are converted
// to float relative to the box centre, so a vertex is off by at most about
// 0.5 * diagonal * 2^-24 = 3e-8 diagonal: 1e-5 leaves a margin of ~300 over that rounding, yet
// stays far below any wall thickness worth baking (1e-5 of the object's size).
inline constexpr double kRayEpsilonRelative = 1e-5;

// Upper bound on --rays: far past where 8-bit (or float) colours stop changing.
inline constexpr int kMaxRays = 1 << 20;

struct BakeSettings {
  int rays = 256;  // rays per vertex (or texel), >= 1
  // Max ray distance in scene units; when unset, max_distance_relative * bbox diagonal.
  std::optional<double> max_distance;
  double max_distance_relative = kDefaultMaxDistanceRelative;
  Distribution distribution = Distribution::Cosine;
  Estimator estimator = Estimator::Occlusion;
  Sampler sampler = Sampler::Stratified;
  // Every ray's random numbers are a hash of (seed, vertex or texel index, ray index): the result
  // does not depend on the thread count or the order in which vertices are processed.
  std::uint64_t seed = 0;
  int threads = 0;  // 0: std::thread::hardware_concurrency()
};

// translucency = lerp(min, max, occlusion) * tint, per channel, in [0, 1].
struct ColorMap {
  double min = 0.0;  // translucency of a vertex whose rays all escape (thick)
  double max = 1.0;  // translucency of a vertex whose rays all hit at once (thin)
  glm::dvec3 tint{1.0, 1.0, 1.0};
};

// Throws InputError naming the option (e.g. "--rays: must be in [1, 1048576], got 0").
void validate(const BakeSettings& settings);
void validate(const ColorMap& map);

// Called from the calling thread only, after each batch of vertices (or texels).
using Progress = std::function<void(std::size_t done, std::size_t total)>;

}  // namespace lt::bake
