// A stored mesh judged by Dolphin (issue 46 step 3): the FIFO log declares each attribute's
// storage in the VAT (GX_SetVtxAttrFmt's type, count and fraction, ByteDequant as libogc sets
// it), sends each object's vertices in those types in its own coordinates with the object's
// position and normal matrices, and Dolphin's vertex loader reads the very bytes. Its frame must
// be ltrender's `:out=xfb` picture, pixel for pixel. Two demo scenes (a sphere with UVs and an
// albedo map: GX_TEX_ST beside t; two cubes moved, turned and scaled, so the object matrices
// matter) x two storages (positions s16, normals s8, RGB565, s16 texture coordinates; and s8
// positions, s16 normals, RGBA4, s8 texture coordinates), one Dolphin start a scene. Not u8/u16: t
// = dot(V, -H) is signed, so an unsigned texture coordinate cannot hold it, and the demo meshes'
// positions are centred on their origin. A third frame is a program file declaring the storage
// as a game does (the generated F32 program with GX_S16, 8 positions and GX_S8 normals, issue 46
// step 4): Dolphin plays the log the declarations give, ltrender renders the file. Two more
// frames (issue 46 step 8) draw with other vertex formats and an NBT: GX_VTXFMT3 with s8 NBT
// normals sent directly, and GX_VTXFMT7 with s16 NBT3 normals indexed in a display list (three
// indices a normal), so Dolphin's loader is looked up by the draw's format and reads the NBT's
// vectors where ltrender's does. Two more (issue 46 step 9) are two frames of the camera path
// under t=vertex stored in a display list: the list's bytes are the same each frame, the t array
// it indexes (one element per vertex, its s16 fraction chosen from the frame's t) is rewritten,
// as a stored module does it (gx_module_stored_test.cpp holds the module's sends to this log).
#include <gtest/gtest.h>

#include "dolphin_util.h"
#include "gx/program/printer.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"

namespace lt {
namespace {

class DolphinVertexStorage : public ::testing::TestWithParam<std::string> {};

TEST_P(DolphinVertexStorage, DolphinsFramesOfAStoredMeshAreLtrendersXfbPictures) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  test::TempDir dir;
  std::string program =
      gx::print_program(gx::generate_programs(scene, gx::parse_gx_variant("t=vertex")).file);
  for (const auto& [from, to] :
       {std::pair<std::string, std::string>{"GX_POS_XYZ, GX_F32, 0", "GX_POS_XYZ, GX_S16, 8"},
        {"GX_NRM_XYZ, GX_F32, 0", "GX_NRM_XYZ, GX_S8, 0"}}) {
    for (size_t at = program.find(from); at != std::string::npos; at = program.find(from, at))
      program.replace(at, from.size(), to);
  }
  ASSERT_NE(program.find("GX_S16, 8"), std::string::npos) << "no position declaration edited";
  test::write_file(dir / "declared.c", program);
  const std::vector<test::JudgedFrame> frames{
      {"t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto", ""},
      {"t=vertex:vtx=s8/auto:nrm=s16:clr=rgba4:uv=s8/auto", ""},
      {"t=vertex", (dir / "declared.c").string()},
      {"t=vertex:vtx=s16/auto:nrm=s8/nbt:clr=rgb565:uv=s16/auto:vat=3", ""},
      {"t=vertex:vtx=s16/auto:nrm=s16/nbt3:clr=rgba4:uv=s16/auto:draw=list:vat=7", ""},
      {"t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list", "", 3},
      {"t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list", "", 6}};
  const std::vector<test::JudgedRow> rows =
      test::expect_dolphins_pictures(scene, frames, GetParam());
  for (size_t k = 0; k < rows.size(); ++k)
    EXPECT_GT(rows[k].covered, static_cast<size_t>(test::kDolphinWidth * test::kDolphinHeight / 50))
        << frames[k].variant << ": the scene covers almost nothing";
}

INSTANTIATE_TEST_SUITE_P(DemoScenes, DolphinVertexStorage,
                         ::testing::Values("scenes/albedo_checker.json",
                                           "scenes/coloured_cubes.json"),
                         [](const auto& info) { return test::scene_param_name(info.param); });

}  // namespace
}  // namespace lt
