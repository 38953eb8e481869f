// The CPU paths' G-buffer pass (issue 39): the float G-buffer's rasterisation through llvmpipe and
// its read-back, on each demo scene at 1280x720, beside the reference's whole frame (the pass,
// the gather into runs and the shading, on one thread) and flat's frame on the same context: the
// part of a reference or half frame that is not shading, and the baseline the bench divides by.
//
//   LP_NUM_THREADS=0 taskset -c 1 build/bench_gbuffer --benchmark_counters_tabular=true
//
// One core, llvmpipe drawing in the calling thread, as `ltrender bench` times the paths.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

#include "core/build_paths.h"
#include "core/parallel_rows.h"
#include "load/load_scene.h"
#include "paths/common/gbuffer.h"
#include "paths/path.h"
#include "render/session.h"

namespace {

const std::vector<std::string>& demo_scenes() {
  static const std::vector<std::string> names = {
      "albedo_checker",      "backlit_sphere", "baked_blob",    "coloured_cubes",
      "debian_box_textured", "teapot_vertex",  "thin_vs_thick", "three_point_blob"};
  return names;
}

struct SceneAtWideSize {
  explicit SceneAtWideSize(const std::string& name)
      : scene(lt::load_scene(lt::build_paths::source_dir() / "scenes" / (name + ".json"))),
        session(scene, 1280, 720) {}
  lt::Scene scene;
  lt::RenderSession session;
};

// Arg: the scene's index in demo_scenes().
void BM_GBufferPass(benchmark::State& state) {
  SceneAtWideSize s(demo_scenes()[static_cast<size_t>(state.range(0))]);
  lt::GBuffer gbuffer(s.session.context(), "bench_gbuffer");
  for (auto _ : state) gbuffer.rasterise();  // ends in glReadPixels, so the drawing is done
  state.SetLabel(demo_scenes()[static_cast<size_t>(state.range(0))]);
}

void BM_FlatFrame(benchmark::State& state) {
  SceneAtWideSize s(demo_scenes()[static_cast<size_t>(state.range(0))]);
  std::unique_ptr<lt::Path> flat = s.session.build(lt::find_path("flat"), "");
  for (auto _ : state) {
    flat->frame();
    glFinish();
  }
  state.SetLabel(demo_scenes()[static_cast<size_t>(state.range(0))]);
}

// One thread, as `ltrender bench` times the CPU paths.
void BM_ReferenceFrame(benchmark::State& state) {
  SceneAtWideSize s(demo_scenes()[static_cast<size_t>(state.range(0))]);
  const unsigned saved = lt::worker_threads_setting().load();
  lt::worker_threads_setting() = 1;
  std::unique_ptr<lt::Path> reference = s.session.build(lt::find_path("reference"), "");
  for (auto _ : state) {
    reference->frame();
    glFinish();
  }
  lt::worker_threads_setting() = saved;
  state.SetLabel(demo_scenes()[static_cast<size_t>(state.range(0))]);
}

BENCHMARK(BM_GBufferPass)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReferenceFrame)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FlatFrame)->DenseRange(0, 7)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  // llvmpipe draws in the calling thread unless told otherwise, as the bench pins one core.
  ::setenv("LP_NUM_THREADS", "0", 0);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
