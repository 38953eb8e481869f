// The CPU paths' per-pixel stages (issue 39): pixels per second of the half path's fp16 shading
// and the reference's double shading, a run of 64 G-buffer pixels at a time in vector lanes, and
// what each did before (Imath's software rounding, model::shade a pixel at a time); values per
// second of the fp16 rounding alone, of the lobe's power and of a map's sample, each in lanes
// and as before. Light evaluations per second ("light_evals") are pixels
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
#include "core/simd_target.h"
#include "load/load_scene.h"
#include "model/lobe_power.h"
#include "model/texture_sampling.h"
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
  state.SetLabel(lt::simd_target());
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

// The lobe's t^p for a whole p: model::lobe_power in vector lanes (the reference's), and std::pow
// a value at a time as the reference called it before. t over (0, 1], with every bit of a
// double's mantissa used.
std::vector<double> lobe_bases() {
  std::vector<double> t(4096);
  for (size_t i = 0; i < t.size(); ++i)
    t[i] = std::fmod((static_cast<double>(i) + 1.0) * 0.6180339887498949, 1.0) + 1e-9;
  return t;
}

void values_per_second(benchmark::State& state, size_t n) {
  state.counters["values"] =
      benchmark::Counter(static_cast<double>(state.iterations() * n), benchmark::Counter::kIsRate);
}

// Arg: the power.
void BM_LobePowerLanes(benchmark::State& state) {
  const std::vector<double> t = lobe_bases();
  std::vector<double> out(t.size());
  size_t calls = 0;
  for (auto _ : state) {
    calls =
        lt::model::lobe_power(t.data(), static_cast<double>(state.range(0)), out.data(), t.size());
    benchmark::DoNotOptimize(out.data());
  }
  values_per_second(state, t.size());
  state.counters["std_pow_share"] = static_cast<double>(calls) / static_cast<double>(t.size());
}
BENCHMARK(BM_LobePowerLanes)->ArgName("p")->Arg(3)->Arg(8)->Arg(32);

void BM_StdPow(benchmark::State& state) {
  const std::vector<double> t = lobe_bases();
  std::vector<double> out(t.size());
  const double p = static_cast<double>(state.range(0));
  for (auto _ : state) {
    for (size_t i = 0; i < t.size(); ++i) out[i] = std::pow(t[i], p);
    benchmark::DoNotOptimize(out.data());
  }
  values_per_second(state, t.size());
}
BENCHMARK(BM_StdPow)->ArgName("p")->Arg(3)->Arg(8)->Arg(32);

// A map's bilinear sample: in the reference's lanes, and model::sample_bilinear a sample at a
// time. A 512 x 512 REPEAT texture (debian_box_textured's albedo map is one), coordinates over
// [-0.5, 1.5] so both the inside and the wrapped taps are taken.
struct MapSamples {
  lt::model::Texture texture;
  std::vector<double> u, v;
  MapSamples() {
    texture.width = texture.height = 512;
    texture.wrap_s = texture.wrap_t = lt::model::Wrap::Repeat;
    texture.texels.resize(512 * 512 * 3);
    for (size_t i = 0; i < texture.texels.size(); ++i)
      texture.texels[i] = static_cast<float>(i % 251) / 250.0f;
    for (int i = 0; i < 4096; ++i) {
      u.push_back(-0.5 + 2.0 * ((i * 37) % 4096) / 4096.0);
      v.push_back(-0.5 + 2.0 * ((i * 101) % 4096) / 4096.0);
    }
  }
};

void BM_SampleBilinearLanes(benchmark::State& state) {
  const MapSamples m;
  std::vector<double> rgb(3 * m.u.size());
  for (auto _ : state) {
    lt::reference::sample_bilinear(m.texture, m.u.data(), m.v.data(), rgb.data(), m.u.size());
    benchmark::DoNotOptimize(rgb.data());
  }
  values_per_second(state, m.u.size());
}
BENCHMARK(BM_SampleBilinearLanes);

void BM_SampleBilinearScalar(benchmark::State& state) {
  const MapSamples m;
  for (auto _ : state) {
    for (size_t i = 0; i < m.u.size(); ++i)
      benchmark::DoNotOptimize(lt::model::sample_bilinear(m.texture, {m.u[i], m.v[i]}));
  }
  values_per_second(state, m.u.size());
}
BENCHMARK(BM_SampleBilinearScalar);

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
  state.SetLabel(lt::simd_target());
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
