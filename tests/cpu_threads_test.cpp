// The CPU paths' per-pixel stages on any number of workers (core/parallel_rows.h): rows go to
// whichever worker is free, so which worker shades a row differs from frame to frame, and
// `bench --cpu-threads` sets how many there are. Neither may change a bit of the image or a
// counter: every row computes the same whoever takes it.
#include <gtest/gtest.h>

#include "arb_test_util.h"
#include "core/parallel_rows.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

struct Frame {
  Image image;
  FrameStats stats;
};

Frame render_with_workers(const Scene& scene, const std::string& path_name, unsigned workers) {
  worker_threads_setting() = workers;
  RenderSession session(scene, 160, 120);
  const PathInfo& info = find_path(path_name);
  auto path = session.build(info, info.variants.front().name);
  path->frame();
  path->frame();  // a second frame reuses the first one's buffers
  Frame f{path->result(), path->frame_stats()};
  worker_threads_setting() = 0;
  return f;
}

class CpuThreads : public ::testing::TestWithParam<std::string> {};

TEST_P(CpuThreads, OneWorkerAndThreeGiveTheSameBits) {
  const Scene scene = test::load_test_scene("scenes/three_point_blob.json");
  const Frame one = render_with_workers(scene, GetParam(), 1);
  const Frame three = render_with_workers(scene, GetParam(), 3);
  ASSERT_EQ(one.image.rgba.size(), three.image.rgba.size());
  EXPECT_TRUE(one.image.rgba == three.image.rgba);
  EXPECT_GT(test::covered_pixels(one.image), 1000u);
  // The counters summed over workers agree too (covered pixels, TEV stage-pixels).
  EXPECT_EQ(one.stats.covered_pixels, three.stats.covered_pixels);
  EXPECT_EQ(one.stats.tev_stage_pixels, three.stats.tev_stage_pixels);
  if (one.stats.threads) {
    EXPECT_EQ(*one.stats.threads, 1.0);
    EXPECT_EQ(*three.stats.threads, 3.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, CpuThreads, ::testing::Values("reference", "half", "gx"));

// `--threads N` (render, regress, advise): taken, said in --help with the default it stands
// for, and N = 0 refused as bad input (exit 2), not read as "every core".
TEST(ThreadsOption, EveryRenderingCommandTakesItAndSaysItsDefault) {
  for (const char* command : {"render", "regress", "advise"}) {
    const test::RunResult help = test::run_ltrender(std::string(command) + " --help");
    EXPECT_EQ(help.exit_code, 0) << command;
    EXPECT_NE(help.out.find("--threads"), std::string::npos) << command;
    EXPECT_NE(help.out.find("every core this process may use"), std::string::npos) << command;
  }
  test::TempDir dir;
  const std::string scene = (test::source_dir() / "scenes/backlit_sphere.json").string();
  const std::string out = (dir / "one.exr").string();
  EXPECT_EQ(
      test::run_ltrender("render " + scene + " --path reference --threads 1 -o " + out).exit_code,
      0);
  EXPECT_TRUE(fs::exists(out));
  const test::RunResult zero =
      test::run_ltrender("render " + scene + " --path reference --threads 0 -o " + out);
  EXPECT_EQ(zero.exit_code, 2);
  EXPECT_NE(zero.err.find("--threads"), std::string::npos) << zero.err;
}

}  // namespace
}  // namespace lt
