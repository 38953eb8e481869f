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
// in the emulator makes 7-10 pixels differ). Where the scene sends a vertex colour (baked_blob),
// a fifth frame is a program file sending it in GX_VA_CLR1 alone, as RGB565 (issue 46 step 8):
// Dolphin directs a lone colour to channel 0, where ltrender reads it.
#include <gtest/gtest.h>

#include "dolphin_util.h"
#include "gx/program/printer.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"

namespace lt {
namespace {

class DolphinVertexDraw : public ::testing::TestWithParam<std::string> {};

TEST_P(DolphinVertexDraw, DolphinsFramesOfIndexedStripsAndListsAreLtrendersXfbPictures) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  const std::string stored = "t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto";
  std::vector<test::JudgedFrame> frames{{stored + ":draw=indexed", ""},
                                        {stored + ":draw=strips", ""},
                                        {stored + ":draw=list", ""},
                                        {"t=vertex:draw=list", ""}};
  test::TempDir dir;
  std::string program =
      gx::print_program(gx::generate_programs(scene, gx::parse_gx_variant("t=vertex")).file);
  if (program.find("GX_SetVtxDesc(GX_VA_CLR0") != std::string::npos) {
    for (const auto& [from, to] :
         {std::pair<std::string, std::string>{"GX_SetVtxDesc(GX_VA_CLR0",
                                              "GX_SetVtxDesc(GX_VA_CLR1"},
          {"GX_VA_CLR0, GX_CLR_RGBA, GX_RGBA8, 0", "GX_VA_CLR1, GX_CLR_RGB, GX_RGB565, 0"}}) {
      for (size_t at = program.find(from); at != std::string::npos; at = program.find(from, at))
        program.replace(at, from.size(), to);
    }
    test::write_file(dir / "clr1.c", program);
    frames.push_back({"t=vertex", (dir / "clr1.c").string()});
  }
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
