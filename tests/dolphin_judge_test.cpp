// The Wii path judged by an implementation that is not ltrender's (issues 25 and 38): every demo
// scene (scenes/*.json, scenes/ortho, scenes/maps, the glTF demo) through every gx variant that
// renders it becomes a Dolphin FIFO log, Dolphin's software renderer plays it (dolphin-emu-nogui
// under a private Xvfb, judge/dolphin_player.h), and Dolphin's frame must be ltrender's own
// picture of the console's output, `:out=xfb`, pixel for pixel: zero pixels differ. The gx path
// rasterises as Dolphin's software renderer does (src/gx/rasteriser.h, clipper.h), so
// nothing is left to bound. docs/dolphin-judge.md has the table these tests print.
//
// One log carries every variant of four scenes, each a frame of its own (one Dolphin start for
// the four: a start and stop is ~0.7 s whatever the log holds, docs/testing.md "Test time").
// Not judged here: :out=xfb (what the others are compared through), and :colors=round and
// :lights=round-each, which model Dolphin's shader backends, not its software renderer (against
// it they differ by 1 LSB in thousands of pixels: docs/dolphin-judge.md), and :coverage=console,
// which models the console where the hwtests show Dolphin differs (test::judged_variants).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include "dolphin_util.h"
#include "gx_module_host/host_module.h"
#include "judge/dolphin_player.h"
#include "load/load_scene.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/module/module_exporter.h"
#include "render/camera_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

constexpr int kWidth = test::kDolphinWidth, kHeight = test::kDolphinHeight;

std::vector<std::string> judged_scenes() {
  std::vector<std::string> scenes;
  for (const char* folder : {"scenes", "scenes/ortho", "scenes/maps"}) {
    for (const std::string& s : test::json_files(folder)) scenes.push_back(s);
  }
  scenes.push_back("scenes/gltf/blob.glb");
  return scenes;
}

// The scenes in groups of four, a group one log (one Dolphin start:
// test::expect_dolphins_pictures).
constexpr size_t kScenesALog = 4;
std::vector<std::vector<std::string>> judged_scene_groups() {
  const std::vector<std::string> scenes = judged_scenes();
  std::vector<std::vector<std::string>> groups;
  for (size_t i = 0; i < scenes.size(); i += kScenesALog)
    groups.emplace_back(
        scenes.begin() + static_cast<std::ptrdiff_t>(i),
        scenes.begin() + static_cast<std::ptrdiff_t>(std::min(scenes.size(), i + kScenesALog)));
  return groups;
}

class DolphinJudge : public ::testing::TestWithParam<std::vector<std::string>> {};

TEST_P(DolphinJudge, DolphinsFramesAreLtrendersXfbPictures) {
  std::vector<Scene> scenes;
  for (const std::string& file : GetParam())
    scenes.push_back(load_scene(test::source_dir() / file));
  std::vector<test::JudgedScene> judged;
  for (size_t s = 0; s < scenes.size(); ++s) {
    test::JudgedScene js{&scenes[s], {}, GetParam()[s]};
    for (const std::string& v : test::judged_variants(scenes[s])) js.frames.push_back({v, ""});
    ASSERT_FALSE(js.frames.empty()) << GetParam()[s];
    judged.push_back(std::move(js));
  }
  const std::vector<std::vector<test::JudgedRow>> rows = test::expect_dolphins_pictures(judged);
  for (size_t s = 0; s < rows.size(); ++s) {
    for (size_t k = 0; k < rows[s].size(); ++k)
      EXPECT_GT(rows[s][k].covered, static_cast<size_t>(kWidth * kHeight / 50))
          << GetParam()[s] << " " << judged[s].frames[k].variant
          << ": the scene covers almost nothing";
  }
}

// The module's animation (issue 26) as one FIFO log: the exported module compiled on the host
// (gx_module_host/host_module.h) drives 8 frames along the camera path (render/camera_path.h),
// each frame's programs are the ones its pass functions print, and the log carries the 8 frames,
// each with its own camera and vertices. Dolphin plays them in order; each dump must be
// ltrender's `:out=xfb` picture of that frame, pixel for pixel (test::dolphin_pictures maps the
// dumps to the frames). A dump matched to the wrong frame fails: the camera moves 10 degrees a
// frame. Four modules: the sphere's default, three_point_blob's two :view=object programs,
// whose texture matrix and XF specular light the module recomputes each frame, and the latter
// stored (s16 positions, s8 normals, RGB565 colours) and drawn from a display list.
struct AnimationCase {
  std::string scene, variant;
};
void PrintTo(const AnimationCase& c, std::ostream* out) {
  *out << c.scene << " --variant " << c.variant;
}

class DolphinJudgeAnimation : public ::testing::TestWithParam<AnimationCase> {};

TEST_P(DolphinJudgeAnimation, EachFrameOfTheModuleDrivenLogIsLtrendersPicture) {
  const AnimationCase& c = GetParam();
  Scene base = load_scene(test::source_dir() / c.scene);
  gx::test_module::make_float(base);
  base.width = kWidth;
  base.height = kHeight;
  const gx::GxVariant variant = gx::parse_gx_variant(c.variant);
  test::TempDir dir;
  const gx::test_module::HostModule host(dir, gx::export_module(base, variant, c.scene));
  ASSERT_TRUE(host.compiled) << host.compiler_output;
  const gx::ScenePlan plan = gx::plan_scene(base, variant);
  std::vector<Scene> scenes;
  for (int k = 0; k < kCameraPathFrames; ++k) scenes.push_back(scene_on_camera_path(base, k));
  std::vector<gx::ScenePrograms> programs;
  for (int k = 0; k < kCameraPathFrames; ++k) {
    const std::string text = gx::test_module::drive_frame(host, plan, scenes[k]);
    ASSERT_FALSE(text.empty());
    const fs::path file = dir / ("frame" + std::to_string(k) + ".c");
    test::write_file(file, text);
    // A stored variant's programs declare its storage: read with the variant's other axes
    // (program_storage.h declared_variant); the log still stores each object as the variant does.
    gx::GxVariant undeclared = variant;
    undeclared.storage = gx::VertexStorage{};
    programs.push_back(gx::scene_programs_for(scenes[k], undeclared, file.string()));
  }
  std::vector<gx::fifo::FrameInput> inputs;
  for (int k = 0; k < kCameraPathFrames; ++k) inputs.push_back({variant, &programs[k], &scenes[k]});
  const std::vector<Image> dumps = test::dolphin_pictures(base, inputs);
  ASSERT_EQ(dumps.size(), static_cast<size_t>(kCameraPathFrames));
  for (int k = 0; k < kCameraPathFrames; ++k) {
    const Image ours = render_scene(scenes[k], "gx", c.variant + ":out=xfb", kWidth, kHeight);
    const test::PictureDifference d = test::picture_difference(ours, dumps[static_cast<size_t>(k)]);
    std::printf("| %s | %s | frame %d | %zu | %d |\n", c.scene.c_str(), c.variant.c_str(), k,
                d.differ, d.max);
    EXPECT_EQ(d.differ, 0u) << "frame " << k << ": first at " << d.first_x << "," << d.first_y
                            << ", max " << d.max << " LSB";
  }
}

INSTANTIATE_TEST_SUITE_P(
    ModuleAnimation, DolphinJudgeAnimation,
    ::testing::Values(AnimationCase{"scenes/backlit_sphere.json", "t=vertex"},
                      AnimationCase{"scenes/three_point_blob.json", "t=texgen:view=object"},
                      AnimationCase{"scenes/three_point_blob.json", "lobe=xf-spec:view=object"},
                      // A stored module's variant (module_stored.h): quantised arrays and a
                      // display list, whose sends gx_module_stored_test.cpp holds to this log.
                      AnimationCase{"scenes/three_point_blob.json",
                                    "lobe=xf-spec:view=object:vtx=s16/auto:nrm=s8:clr=rgb565:"
                                    "draw=list"}),
    [](const auto& info) {
      return test::test_param_name(info.param.scene + "_" + info.param.variant);
    });

INSTANTIATE_TEST_SUITE_P(DemoScenes, DolphinJudge, ::testing::ValuesIn(judged_scene_groups()),
                         [](const auto& info) {
                           return test::scene_param_name(info.param.front()) + "_to_" +
                                  test::scene_param_name(info.param.back());
                         });

}  // namespace
}  // namespace lt
