// Thickness baker throughput (issue 3): rays per second through lt::bake::bake_occlusion, the
// Embree BVH build included (a bake always pays for it once). The "rays" counter is the rate;
// the target is 100k vertices x 256 rays within 5 s on two cores, i.e. >= 5.1 Mrays/s.
//
//   build/bench_bake --benchmark_counters_tabular=true
#include <benchmark/benchmark.h>

#include <map>
#include <thread>
#include <utility>

#include "bake/thickness_baker.h"
#include "mesh/meshgen.h"

namespace {

enum Shape : int { kSphere = 0, kBlob = 1 };

// Meshes are built once per (shape, subdivisions), outside the timed loop.
const lt::bake::Surface& surface(int shape, int subdivisions) {
  static std::map<std::pair<int, int>, lt::bake::Surface> cache;
  auto it = cache.find({shape, subdivisions});
  if (it == cache.end()) {
    const lt::PolyMesh mesh = shape == kSphere ? lt::meshgen::icosphere(1.0, subdivisions)
                                               : lt::meshgen::blob(subdivisions);
    it = cache.emplace(std::make_pair(shape, subdivisions), lt::bake::surface_of(mesh)).first;
  }
  return it->second;
}

// Args: shape, subdivisions, rays per vertex, threads (0: all cores), estimator (0 occlusion,
// 1 distance).
void BM_Bake(benchmark::State& state) {
  const auto& s = surface(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  lt::bake::BakeSettings settings;
  settings.rays = static_cast<int>(state.range(2));
  settings.threads = static_cast<int>(state.range(3));
  settings.estimator =
      state.range(4) == 0 ? lt::bake::Estimator::Occlusion : lt::bake::Estimator::Distance;
  std::uint64_t rays = 0;
  double trace_seconds = 0.0;
  for (auto _ : state) {
    const lt::bake::BakeResult r =
        lt::bake::bake_occlusion(s.positions, s.normals, s.triangles, settings);
    benchmark::DoNotOptimize(r.occlusion.data());
    rays += r.rays_traced;
    trace_seconds += r.trace_seconds;
  }
  state.counters["vertices"] = static_cast<double>(s.positions.size());
  state.counters["rays"] =
      benchmark::Counter(static_cast<double>(rays), benchmark::Counter::kIsRate);
  // Rays over tracing time alone: what `ltrender bake` prints as Mrays/s.
  state.counters["Mrays/s_trace"] =
      trace_seconds > 0.0 ? static_cast<double>(rays) / trace_seconds / 1e6 : 0.0;
}

// Wall time, not CPU time of the main thread: the work is on all cores.
BENCHMARK(BM_Bake)
    ->ArgNames({"shape", "subdiv", "rays", "threads", "estimator"})
    ->Args({kSphere, 5, 256, 1, 0})  // 10242 vertices, one thread
    ->Args({kSphere, 5, 256, 0, 0})  // 10242 vertices, all cores
    ->Args({kBlob, 6, 256, 0, 0})    // 40962 vertices, thin lobes
    ->Args({kBlob, 6, 256, 0, 1})    // distance estimator (closest hits)
    ->Args({kSphere, 7, 256, 0, 0})  // 163842 vertices: the "100k vertex" case
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace

BENCHMARK_MAIN();
