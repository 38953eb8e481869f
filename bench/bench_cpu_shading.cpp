// The CPU paths' per-pixel stages (issue 39): pixels per second of the half path's fp16 shading
// and the reference's double shading, a run of 64 G-buffer pixels at a time in vector lanes, and
// what each did before (Imath's software rounding, model::shade a pixel at a time); values per
// second of the fp16 rounding alone. Light evaluations per second ("light_evals") are pixels
// times the scene's lights: the bench's work axis for these paths (docs/bench.md).
//
//   build/bench_cpu_shading --benchmark_counters_tabular=true
//
// One thread: the figures are a core's, as `ltrender bench` pins one. The lights and materials
// are scenes/three_point_blob.json's (three point lights); the pixels are a sphere's front.
#include <Imath/half.h>
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "core/build_paths.h"
#include "load/load_scene.h"
#include "model/translucency.h"
#include "paths/half/half_shading_lanes.h"
#include "paths/reference/reference_shading_lanes.h"

namespace {

const lt::Scene& demo_scene() {
  static const lt::Scene scene =
      lt::load_scene(lt::build_paths::source_dir() / "scenes/three_point_blob.json");
  return scene;
}

// A full run of the front of a unit sphere 4 units in front of the eye, as a G-buffer holds it.
const lt::PixelRun& sphere_run() {
  static const lt::PixelRun run = [] {
    lt::PixelRun r;
    r.count = lt::kPixelRunCapacity;
    for (size_t i = 0; i < r.count; ++i) {
      const double a = 0.02 * static_cast<double>(i) - 0.6, b = 0.3;
      const double n[3] = {std::sin(a) * std::cos(b), std::sin(b), std::cos(a) * std::cos(b)};
      for (int c = 0; c < 3; ++c) {
        r.normal[c][i] = static_cast<float>(n[c]);
        r.position[c][i] = static_cast<float>(n[c] - (c == 2 ? 4.0 : 0.0));
        r.thickness[c][i] = 0.5f;
      }
      r.uv[0][i] = r.uv[1][i] = 0;
    }
    return r;
  }();
  return run;
}

void count(benchmark::State& state, size_t pixels_per_iteration) {
  const double pixels = static_cast<double>(state.iterations() * pixels_per_iteration);
  state.counters["pixels"] = benchmark::Counter(pixels, benchmark::Counter::kIsRate);
  state.counters["light_evals"] = benchmark::Counter(
      pixels * static_cast<double>(demo_scene().lights.size()), benchmark::Counter::kIsRate);
}

// Arg: the pow mode (0 exact, 1 sg, 2 unguarded).
void BM_HalfShadeRun(benchmark::State& state) {
  const auto mode = static_cast<lt::fp16::PowMode>(state.range(0));
  const lt::fp16::SceneH scene = lt::fp16::prepare_scene(demo_scene(), mode);
  lt::ShadedRun out;
  for (auto _ : state) {
    lt::fp16::shade_run(scene, scene.materials[0], mode, sphere_run(), out);
    benchmark::DoNotOptimize(out.rgb[0][0]);
  }
  count(state, sphere_run().count);
  state.SetLabel(lt::fp16::simd_target());
}
BENCHMARK(BM_HalfShadeRun)->ArgName("mode")->Arg(0)->Arg(1)->Arg(2);

void BM_ReferenceShadeRun(benchmark::State& state) {
  const lt::Scene& scene = demo_scene();
  lt::ShadedRun out;
  for (auto _ : state) {
    lt::reference::shade_run(scene, scene.materials[0], sphere_run(), out);
    benchmark::DoNotOptimize(out.rgb[0][0]);
  }
  count(state, sphere_run().count);
}
BENCHMARK(BM_ReferenceShadeRun);

// The reference before issue 39: model::shade a pixel at a time.
void BM_ReferenceShadeScalar(benchmark::State& state) {
  const lt::Scene& scene = demo_scene();
  const lt::PixelRun& run = sphere_run();
  for (auto _ : state) {
    for (size_t i = 0; i < run.count; ++i) {
      lt::model::SurfacePoint sp;
      sp.P = {run.position[0][i], run.position[1][i], run.position[2][i]};
      sp.N = {run.normal[0][i], run.normal[1][i], run.normal[2][i]};
      sp.V = lt::model::view_vector(scene.camera, sp.P);
      benchmark::DoNotOptimize(lt::model::shade(scene, scene.materials[0], sp));
    }
  }
  count(state, run.count);
}
BENCHMARK(BM_ReferenceShadeScalar);

std::vector<float> operation_results() {
  std::vector<float> v(4096);
  for (size_t i = 0; i < v.size(); ++i) v[i] = 0.001f * static_cast<float>(i) * 1.0009765625f;
  return v;
}

// fp16 rounding alone, float -> nearest half -> float: in lanes (F16C where there is one) ...
void BM_RoundToHalf(benchmark::State& state) {
  const std::vector<float> in = operation_results();
  std::vector<float> out(in.size());
  for (auto _ : state) {
    lt::fp16::round_to_half(in.data(), out.data(), in.size());
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["values"] = benchmark::Counter(static_cast<double>(state.iterations() * in.size()),
                                                benchmark::Counter::kIsRate);
  state.SetLabel(lt::fp16::simd_target());
}
BENCHMARK(BM_RoundToHalf);

// ... and through Imath's half, one value at a time, as the half path rounded before.
void BM_RoundToHalfImath(benchmark::State& state) {
  const std::vector<float> in = operation_results();
  std::vector<float> out(in.size());
  for (auto _ : state) {
    for (size_t i = 0; i < in.size(); ++i) out[i] = float(Imath::half(in[i]));
    benchmark::DoNotOptimize(out.data());
  }
  state.counters["values"] = benchmark::Counter(static_cast<double>(state.iterations() * in.size()),
                                                benchmark::Counter::kIsRate);
}
BENCHMARK(BM_RoundToHalfImath);

}  // namespace

BENCHMARK_MAIN();
