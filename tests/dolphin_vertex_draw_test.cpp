// Indexed arrays, triangle strips and display lists judged by Dolphin (issue 46 step 3): the
// FIFO log sets each array with GX_SetArray's CP registers (base, stride) and sends its bytes as
// a memory update, then draws indices (GX_INDEX8 / GX_INDEX16) as GX_TRIANGLES or
// GX_TRIANGLESTRIP, or calls the strip's display list (CALL_DL) from its own memory update.
// Dolphin's vertex loader reads the arrays and its setup unit builds the strip's triangles; its
// frame must be ltrender's `:out=xfb` picture, pixel for pixel. Two demo scenes x {indexed,
// strips, list} with a quantised storage, and the F32 stream as a display list, one Dolphin start
// a scene: albedo_checker (UVs and an albedo map: GX_TEX_ST beside t) and baked_blob, where the
// strip's order moves pixels against a list (8 of 76,800 stored, 13 F32, up to 3 LSB): there
// Dolphin holds the strip rule itself (setting up each odd triangle from another of its vertices
// in the emulator makes 7-10 pixels differ).
#include <gtest/gtest.h>

#include "dolphin_util.h"
#include "load/load_scene.h"

namespace lt {
namespace {

class DolphinVertexDraw : public ::testing::TestWithParam<std::string> {};

TEST_P(DolphinVertexDraw, DolphinsFramesOfIndexedStripsAndListsAreLtrendersXfbPictures) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  const std::string stored = "t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto";
  const std::vector<test::JudgedFrame> frames{{stored + ":draw=indexed", ""},
                                              {stored + ":draw=strips", ""},
                                              {stored + ":draw=list", ""},
                                              {"t=vertex:draw=list", ""}};
  const std::vector<test::JudgedRow> rows =
      test::expect_dolphins_pictures(scene, frames, GetParam());
  for (size_t k = 0; k < rows.size(); ++k)
    EXPECT_GT(rows[k].covered, static_cast<size_t>(test::kDolphinWidth * test::kDolphinHeight / 50))
        << frames[k].variant << ": the scene covers almost nothing";
}

INSTANTIATE_TEST_SUITE_P(DemoScenes, DolphinVertexDraw,
                         ::testing::Values("scenes/albedo_checker.json", "scenes/baked_blob.json"),
                         [](const auto& info) { return test::scene_param_name(info.param); });

}  // namespace
}  // namespace lt
