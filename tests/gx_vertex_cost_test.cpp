// The console's vertex cost as exact counts (src/gx/vertex_cost.h, src/paths/gx/vertex_budget.h):
// closed forms of libogc's command sizes on small cases, the strip split keeping every triangle,
// and the frame's F32 immediate cost against a second count: the draws of the FIFO log the
// frame records (fifo/frame_recording.h), walked by the command reader.
#include <gtest/gtest.h>

#include "gx/vertex_cost.h"
#include "load/load_scene.h"
#include "paths/gx/frame_recording.h"
#include "gx/fifo/stream_reader.h"
#include "paths/gx/gx_budget.h"
#include "test_util.h"

namespace lt::gx {
namespace {

TEST(GxVertexCost, ImmediateListsSendThreeVerticesATriangleAndAThreeByteBegin) {
  // A quad (2 triangles) of today's 32-byte vertices: 6 vertices, one GX_Begin.
  const DrawCost quad = immediate_list_cost(2, 32);
  EXPECT_EQ(quad.vertices, 6u);
  EXPECT_EQ(quad.draws, 1u);
  EXPECT_EQ(quad.command_bytes, 3u + 6 * 32);
  EXPECT_EQ(quad.fifo_bytes, quad.command_bytes);
  EXPECT_EQ(quad.array_bytes + quad.display_list_bytes, 0u);
  // 30,000 triangles: 90,000 vertices in draws of 65,535 and 24,465.
  const DrawCost big = immediate_list_cost(30000, 32);
  EXPECT_EQ(big.draws, 2u);
  EXPECT_EQ(big.vertices, 90000u);
  EXPECT_EQ(big.command_bytes, 2u * 3 + 90000 * 32);
  EXPECT_EQ(list_draw_counts(90000), (std::vector<std::size_t>{65535, 24465}));
}

TEST(GxVertexCost, LongStripsSplitOnEvenVerticesAndKeepEveryTriangle) {
  EXPECT_EQ(strip_draw_counts(65534), (std::vector<std::size_t>{65534}));
  EXPECT_EQ(strip_draw_counts(65535), (std::vector<std::size_t>{65534, 3}));
  for (std::size_t n : {3u, 4u, 65533u, 65534u, 65535u, 65536u, 131066u, 200001u}) {
    const auto counts = strip_draw_counts(n);
    std::size_t triangles = 0, start = 0;
    for (std::size_t c : counts) {
      EXPECT_LE(c, kMaxBeginVertices);
      EXPECT_EQ(start % 2, 0u) << "a draw starting on an odd vertex flips its winding";
      triangles += c - 2;
      start += c - 2;
    }
    EXPECT_EQ(triangles, n - 2) << n;
  }
}

TEST(GxVertexCost, ADisplayListCostsItsCallAndTheArraysItsFrameSets) {
  IndexedArrays arrays;
  arrays.arrays = {kArrayPosition, kArrayColor0};
  arrays.bytes[kArrayPosition].resize(100);  // 4 lines: 128 bytes
  arrays.bytes[kArrayColor0].resize(40);     // 2 lines: 64
  const DrawCost c = display_list_strip_cost(10, 4, arrays);
  EXPECT_EQ(c.vertices, 10u);
  EXPECT_EQ(c.triangles, 8u);
  EXPECT_EQ(c.command_bytes, 3u + 10 * 4);
  EXPECT_EQ(c.display_list_bytes, 64u);  // 43 bytes padded to 32-byte lines
  EXPECT_EQ(c.array_bytes, 128u + 64);
  EXPECT_EQ(c.fifo_bytes, 9u + 2 * 2 * 6);  // GX_CallDispList, two GX_SetArray of two CP loads
}

TEST(GxVertexCost, TheFramesImmediateCostIsTheFifoLogsDraws) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const GxVariant gv = parse_gx_variant("t=vertex");
  const ScenePrograms programs = scene_programs_for(scene, gv, "");
  const FrameVertexCost cost =
      frame_vertex_cost(scene, programs, parse_vertex_storage("vtx=s16,nrm=s8,clr=rgb565,uv=s16", "t"), "t");
  const fifo::FifoLog log = fifo::record_frames(scene, {{gv, &programs}}, {320, 240});
  fifo::RegisterFile regs;
  const fifo::StreamEvents events = fifo::read_stream(log.frames.at(0).fifo, regs, "frame");
  std::size_t vertices = 0, bytes = 0;
  for (const fifo::StreamDraw& d : events.draws) {
    vertices += d.count;
    bytes += 3 + d.count * d.vertex_size;
  }
  EXPECT_EQ(cost.immediate.draws, events.draws.size());
  EXPECT_EQ(cost.immediate.vertices, vertices);
  EXPECT_EQ(cost.immediate.fifo_bytes, bytes);
  // The stored mesh sends fewer bytes and vertices; every triangle is still set up.
  EXPECT_LT(cost.display_list.vertices, cost.immediate.vertices);
  EXPECT_GE(cost.display_list.triangles, cost.immediate.triangles);
  EXPECT_LT(cost.display_list.fifo_bytes, cost.immediate.fifo_bytes / 100);
  EXPECT_GT(cost.display_list.array_bytes, cost.refreshed_array_bytes);
}

}  // namespace
}  // namespace lt::gx
