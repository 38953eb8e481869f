#include "bake/thickness_baker.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>

#include "core/error.h"
#include "mesh/triangulate.h"

namespace lt::bake {

namespace {

// ---------------------------------------------------------------------------------------------
// Random numbers: counter-based, so that a ray's directions depend only on (seed, vertex, ray)
// and never on which thread traced it or when. splitmix64's finaliser is a bijection on 64 bits
// with full avalanche, which is all a counter-based generator needs.

std::uint64_t mix64(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Nested rather than xor-ed together, so that related triples such as (s, v, r) and (s, r, v)
// give unrelated numbers.
std::uint64_t hash3(std::uint64_t seed, std::uint64_t vertex, std::uint64_t ray) {
  return mix64(mix64(mix64(seed) ^ vertex) ^ ray);
}

// Two uniform numbers in [0, 1) from the two 32-bit halves of a hash: 2^-32 resolution is far
// finer than any ray count we allow.
glm::dvec2 unit_pair(std::uint64_t h) {
  constexpr double k = 1.0 / 4294967296.0;
  return {static_cast<double>(h >> 32) * k, static_cast<double>(h & 0xffffffffull) * k};
}

// Van der Corput in base 2: the bits of i mirrored around the binary point.
double radical_inverse2(std::uint32_t i) {
  i = (i << 16) | (i >> 16);
  i = ((i & 0x00ff00ffu) << 8) | ((i & 0xff00ff00u) >> 8);
  i = ((i & 0x0f0f0f0fu) << 4) | ((i & 0xf0f0f0f0u) >> 4);
  i = ((i & 0x33333333u) << 2) | ((i & 0xccccccccu) >> 2);
  i = ((i & 0x55555555u) << 1) | ((i & 0xaaaaaaaau) >> 1);
  return static_cast<double>(i) * (1.0 / 4294967296.0);
}

double frac(double x) {
  return x - std::floor(x);
}

// Ray index used for the per-vertex Cranley-Patterson shift; real rays use 0..N-1 < 2^20.
constexpr std::uint64_t kShiftStream = ~0ull;

// ---------------------------------------------------------------------------------------------
// Directions.

// Orthonormal basis around unit n without a branch on a "least aligned axis": Duff et al.,
// "Building an Orthonormal Basis, Revisited" (JCGT 2017). Defined for every unit n; the frame
// flips where n.z changes sign, which is harmless: each vertex's azimuths are randomly rotated.
void basis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  const double sign = std::copysign(1.0, n.z);
  const double a = -1.0 / (sign + n.z);
  const double c = n.x * n.y * a;
  t = {1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x};
  b = {c, sign + n.y * n.y * a, -n.y};
}

// (u1, azimuth) -> direction around +z. u1 in [0, 1) picks the polar angle, so stratifying u1
// stratifies cos(theta), which is what the chord test of a sphere depends on. The azimuth comes
// as (cos(phi), sin(phi)).
glm::dvec3 hemisphere(double u1, const glm::dvec2& azimuth, Distribution distribution) {
  // Cosine: cos(theta) = sqrt(1 - u1), sin(theta) = sqrt(u1) (Malley's method: a uniform disk
  // point lifted to the hemisphere). Uniform: cos(theta) = 1 - u1. Both are > 0 for u1 < 1.
  double cos_theta, sin_theta;
  if (distribution == Distribution::Cosine) {
    cos_theta = std::sqrt(1.0 - u1);
    sin_theta = std::sqrt(u1);
  } else {
    cos_theta = 1.0 - u1;
    sin_theta = std::sqrt(std::max(0.0, u1 * (2.0 - u1)));  // 1 - cos^2, without cancellation
  }
  return {sin_theta * azimuth.x, sin_theta * azimuth.y, cos_theta};
}

glm::dvec2 unit_circle(double turns) {
  const double phi = 2.0 * std::numbers::pi * turns;
  return {std::cos(phi), std::sin(phi)};
}

// ---------------------------------------------------------------------------------------------
// Embree, with RAII and errors collected from its callback.

struct EmbreeErrors {
  std::mutex mutex;
  std::string first;
};

void on_embree_error(void* user, RTCError code, const char* str) {
  auto* errors = static_cast<EmbreeErrors*>(user);
  std::lock_guard<std::mutex> lock(errors->mutex);
  if (errors->first.empty()) {
    errors->first = "embree error " + std::to_string(static_cast<int>(code)) + ": " +
                    (str != nullptr ? str : "");
  }
}

class EmbreeScene {
 public:
  EmbreeScene(const std::vector<glm::vec3>& vertices, const std::vector<glm::uvec3>& triangles,
              int threads) {
    // Embree builds its BVH with its own worker threads; cap them like ours.
    const std::string config = "threads=" + std::to_string(threads);
    device_ = rtcNewDevice(config.c_str());
    if (device_ == nullptr) throw std::runtime_error("embree: cannot create a device");
    rtcSetDeviceErrorFunction(device_, on_embree_error, &errors_);

    scene_ = rtcNewScene(device_);
    // ROBUST: no traversal shortcuts that trade accuracy for speed, so a ray cannot slip through
    // the shared edge of two triangles (a leak would read as "unoccluded", i.e. thick). HIGH:
    // spatial splits, a slower build that pays off with hundreds of rays per vertex.
    rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_HIGH);

    RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_HIGH);
    // Embree-owned buffers: they carry the padding its SIMD loads need past the last element.
    auto* v = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                3 * sizeof(float), std::max<std::size_t>(1, vertices.size())));
    auto* t = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                3 * sizeof(unsigned), std::max<std::size_t>(1, triangles.size())));
    if (v == nullptr || t == nullptr) {
      rtcReleaseGeometry(geometry);
      release();
      throw std::runtime_error("embree: cannot allocate geometry buffers");
    }
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      v[3 * i + 0] = vertices[i].x;
      v[3 * i + 1] = vertices[i].y;
      v[3 * i + 2] = vertices[i].z;
    }
    if (vertices.empty()) std::fill(v, v + 3, 0.0f);
    for (std::size_t i = 0; i < triangles.size(); ++i) {
      t[3 * i + 0] = triangles[i].x;
      t[3 * i + 1] = triangles[i].y;
      t[3 * i + 2] = triangles[i].z;
    }
    // No triangles: one all-zero (degenerate) triangle, which Embree skips.
    if (triangles.empty()) std::fill(t, t + 3, 0u);
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene_, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene_);
    if (!errors_.first.empty()) {
      const std::string message = errors_.first;
      release();
      throw std::runtime_error(message);
    }
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() { release(); }

  RTCScene scene() const { return scene_; }
  std::string error() {
    std::lock_guard<std::mutex> lock(errors_.mutex);
    return errors_.first;
  }

 private:
  void release() {
    if (scene_ != nullptr) rtcReleaseScene(scene_);
    if (device_ != nullptr) rtcReleaseDevice(device_);
    scene_ = nullptr;
    device_ = nullptr;
  }

  EmbreeErrors errors_;
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

// ---------------------------------------------------------------------------------------------
// Per-vertex work.

// Rays per Embree stream call: bounds the per-thread buffer whatever --rays is.
constexpr int kRayBlock = 256;

// Vertices per work item. Small enough to balance two threads at the end of a bake and to give a
// smooth progress bar, large enough that the shared counter is touched rarely.
constexpr std::size_t kVertexChunk = 64;

struct VertexJob {
  glm::vec3 origin;   // relative to the box centre, already offset inwards
  glm::dvec3 inward;  // unit flipped normal
  glm::dvec3 tangent, bitangent;
};

struct Tracer {
  RTCScene scene;
  const BakeSettings& settings;
  float epsilon;
  float max_distance;
  // Stratified sampler: (cos, sin) of 2 pi * radical_inverse2(i) for every ray i, computed once
  // per bake. A vertex's random azimuth shift is then a rotation of these, not N sincos calls.
  std::vector<glm::dvec2> azimuths;

  // Occlusion in [0, 1] of one vertex; `vertex` only seeds the random numbers.
  double trace(std::uint64_t vertex, const VertexJob& job, std::vector<RTCRayHit>& buffer) const {
    const int n = settings.rays;
    const glm::dvec2 shift = unit_pair(hash3(settings.seed, vertex, kShiftStream));
    const glm::dvec2 rotation = unit_circle(shift.y);
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    const bool distance = settings.estimator == Estimator::Distance;

    std::uint64_t hits = 0;
    double distance_sum = 0.0;  // sum of min(hit distance, D), for the distance estimator
    for (int begin = 0; begin < n; begin += kRayBlock) {
      const int count = std::min(kRayBlock, n - begin);
      for (int k = 0; k < count; ++k) {
        const int i = begin + k;
        double u1;
        glm::dvec2 azimuth;
        if (settings.sampler == Sampler::Stratified) {
          // Cranley-Patterson rotation of the Hammersley point ((i + 0.5) / N, radical_inverse(i))
          // by `shift`, modulo 1; for the azimuth, adding shift.y turns is a rotation.
          u1 = frac((i + 0.5) / n + shift.x);
          const glm::dvec2 a = azimuths[static_cast<std::size_t>(i)];
          azimuth = {a.x * rotation.x - a.y * rotation.y, a.y * rotation.x + a.x * rotation.y};
        } else {
          const glm::dvec2 u =
              unit_pair(hash3(settings.seed, vertex, static_cast<std::uint64_t>(i)));
          u1 = u.x;
          azimuth = unit_circle(u.y);
        }
        const glm::dvec3 local = hemisphere(u1, azimuth, settings.distribution);
        const glm::vec3 dir(job.tangent * local.x + job.bitangent * local.y + job.inward * local.z);
        RTCRayHit& rh = buffer[static_cast<std::size_t>(k)];
        rh.ray.org_x = job.origin.x;
        rh.ray.org_y = job.origin.y;
        rh.ray.org_z = job.origin.z;
        rh.ray.tnear = epsilon;
        rh.ray.dir_x = dir.x;
        rh.ray.dir_y = dir.y;
        rh.ray.dir_z = dir.z;
        rh.ray.time = 0.0f;
        rh.ray.tfar = max_distance;
        rh.ray.mask = 0xffffffffu;
        rh.ray.id = static_cast<unsigned>(k);
        rh.ray.flags = 0;
        rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rh.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
      }
      if (distance) {
        // Closest hits: a stream of RTCRayHit.
        rtcIntersect1M(scene, &context, buffer.data(), static_cast<unsigned>(count),
                       sizeof(RTCRayHit));
        for (int k = 0; k < count; ++k) {
          const RTCRayHit& rh = buffer[static_cast<std::size_t>(k)];
          const bool hit = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
          distance_sum += hit ? std::min(rh.ray.tfar, max_distance) : max_distance;
        }
      } else {
        // Any-hit queries on the RTCRay part of the same buffer (stride RTCRayHit); Embree sets
        // tfar to -inf for an occluded ray. A stream of one vertex's rays measured ~1.5x faster
        // per core than rtcOccluded1 in a loop and ~10% faster than 16-wide packets here.
        rtcOccluded1M(scene, &context, &buffer[0].ray, static_cast<unsigned>(count),
                      sizeof(RTCRayHit));
        for (int k = 0; k < count; ++k) {
          if (buffer[static_cast<std::size_t>(k)].ray.tfar < 0.0f) ++hits;
        }
      }
    }
    if (distance)
      return std::clamp(1.0 - distance_sum / (static_cast<double>(max_distance) * n), 0.0, 1.0);
    return static_cast<double>(hits) / n;
  }
};

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

bool usable(const glm::dvec3& v) {
  const double len = glm::length(v);
  return std::isfinite(len) && len > 0.0;
}

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

void validate(const BakeSettings& s) {
  if (s.rays < 1 || s.rays > kMaxRays) {
    throw InputError(
        "--rays", "",
        "must be in [1, " + std::to_string(kMaxRays) + "], got " + std::to_string(s.rays));
  }
  if (s.max_distance && !(std::isfinite(*s.max_distance) && *s.max_distance > 0.0)) {
    throw InputError("--max-distance", "", "must be a finite number > 0");
  }
  if (!(std::isfinite(s.max_distance_relative) && s.max_distance_relative > 0.0)) {
    throw InputError("--max-distance-relative", "", "must be a finite number > 0");
  }
  if (s.threads < 0 || s.threads > 1024) {
    throw InputError("--threads", "", "must be in [0, 1024] (0: all cores)");
  }
}

void validate(const ColorMap& m) {
  auto in_unit = [](double x) { return std::isfinite(x) && x >= 0.0 && x <= 1.0; };
  if (!in_unit(m.min)) throw InputError("--min", "", "must be in [0, 1]");
  if (!in_unit(m.max)) throw InputError("--max", "", "must be in [0, 1]");
  if (m.min > m.max) {
    // Thin parts are bright (GDC 2011): an inverted map would be plain AO, not thickness.
    throw InputError("--min", "",
                     "must not exceed --max (thin parts get --max, thick parts --min)");
  }
  if (!in_unit(m.tint.x) || !in_unit(m.tint.y) || !in_unit(m.tint.z)) {
    throw InputError("--tint", "", "each of R,G,B must be in [0, 1]");
  }
}

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
  unsigned hw = std::thread::hardware_concurrency();
  result.threads = settings.threads > 0 ? settings.threads : static_cast<int>(std::max(1u, hw));
  if (nv == 0) return result;

  // Bounding box in double; Embree gets float positions relative to its centre, so a mesh far
  // from the origin (coordinates near 1e6) keeps its float precision relative to its own size.
  glm::dvec3 lo(std::numeric_limits<double>::infinity());
  glm::dvec3 hi(-std::numeric_limits<double>::infinity());
  for (const auto& p : positions) {
    LT_CHECK(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z),
             "finite positions (read_mesh rejects NaN/Inf)");
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::dvec3 centre = 0.5 * (lo + hi);
  const double diagonal = glm::length(hi - lo);
  result.epsilon = kRayEpsilonRelative * diagonal;
  result.max_distance =
      settings.max_distance ? *settings.max_distance : settings.max_distance_relative * diagonal;

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
    if (usable(normals[v])) normal_sum[g] += glm::normalize(normals[v]);
  }
  // Fallback where no copy has a usable normal: the area-weighted normal of the faces around the
  // position (a cross product's length is twice its triangle's area).
  bool any_missing = false;
  for (const auto& n : normal_sum) any_missing = any_missing || !usable(n);
  if (any_missing) {
    std::vector<glm::dvec3> face_sum(ng, glm::dvec3(0.0));
    for (const auto& t : triangles) {
      const glm::dvec3 n =
          glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
      if (!usable(n)) continue;
      for (const unsigned v : {t.x, t.y, t.z}) face_sum[weld.id[v]] += n;
    }
    for (std::size_t g = 0; g < ng; ++g) {
      if (!usable(normal_sum[g])) normal_sum[g] = face_sum[g];
    }
  }
  // The positions to trace, in the order of their first vertex. A position whose normals cancel
  // (a double-sided sheet) or that touches no face with area has no inside: occlusion 0.
  std::vector<std::uint32_t> tasks;
  for (std::size_t v = 0; v < nv; ++v) {
    const std::uint32_t g = weld.id[v];
    if (!usable(normal_sum[g])) {
      ++result.vertices_without_normal;
    } else if (representative[g] == v) {
      tasks.push_back(g);
    }
  }
  const std::size_t n_tasks = tasks.size();
  std::vector<double> occlusion(ng, 0.0);

  // Nothing to hit, or nowhere to go: all-degenerate geometry (every point the same), or a max
  // distance that does not reach past the origin offset. Every vertex is unoccluded.
  if (!(diagonal > 0.0) || !(result.max_distance > result.epsilon) || n_tasks == 0) {
    if (progress) progress(n_tasks, n_tasks);
    return result;
  }

  const auto build_start = std::chrono::steady_clock::now();
  std::vector<glm::vec3> relative(nv);
  for (std::size_t v = 0; v < nv; ++v) relative[v] = glm::vec3(positions[v] - centre);
  EmbreeScene embree(relative, triangles, result.threads);
  result.build_seconds = seconds_since(build_start);

  Tracer tracer{embree.scene(),
                settings,
                static_cast<float>(result.epsilon),
                static_cast<float>(result.max_distance),
                {}};
  if (settings.sampler == Sampler::Stratified) {
    tracer.azimuths.resize(static_cast<std::size_t>(settings.rays));
    for (std::size_t i = 0; i < tracer.azimuths.size(); ++i) {
      tracer.azimuths[i] = unit_circle(radical_inverse2(static_cast<std::uint32_t>(i)));
    }
  }

  // Work sharing: threads take chunks of positions from a shared counter; each result goes to
  // its own slot and its random numbers are seeded by its first vertex's index, so the output is
  // the same whatever the thread count or schedule.
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> done{0};
  auto work = [&](bool report) {
    std::vector<RTCRayHit> buffer(static_cast<std::size_t>(std::min(settings.rays, kRayBlock)));
    for (;;) {
      const std::size_t begin = next.fetch_add(kVertexChunk);
      if (begin >= n_tasks) break;
      const std::size_t end = std::min(n_tasks, begin + kVertexChunk);
      for (std::size_t k = begin; k < end; ++k) {
        const std::uint32_t g = tasks[k];
        const std::uint32_t v = representative[g];
        VertexJob job;
        job.inward = -glm::normalize(normal_sum[g]);
        basis(job.inward, job.tangent, job.bitangent);
        // Origin pushed inside along the flipped normal by epsilon (see kRayEpsilonRelative),
        // computed in double before the float conversion.
        job.origin = glm::vec3(positions[v] - centre + result.epsilon * job.inward);
        occlusion[g] = tracer.trace(v, job, buffer);
      }
      const std::size_t finished = done.fetch_add(end - begin) + (end - begin);
      if (report && progress) progress(finished, n_tasks);
    }
  };

  const auto trace_start = std::chrono::steady_clock::now();
  {
    std::vector<std::jthread> workers;
    for (int i = 1; i < result.threads; ++i) workers.emplace_back(work, false);
    work(true);  // the calling thread works too, and is the one that reports progress
  }
  result.trace_seconds = seconds_since(trace_start);
  if (progress) progress(n_tasks, n_tasks);

  const std::string error = embree.error();
  if (!error.empty()) throw std::runtime_error(error);
  for (std::size_t v = 0; v < nv; ++v) result.occlusion[v] = occlusion[weld.id[v]];
  result.rays_traced =
      static_cast<std::uint64_t>(n_tasks) * static_cast<std::uint64_t>(settings.rays);
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
