// How the vertices are sent (issue 46 step 3, the gx variant's :draw= axis): direct, indexed
// into arrays, as triangle strips, or as strips in a display list.
// - the axis parses, round-trips and refuses a bad value in one line naming the key;
// - indexed GX_TRIANGLES read the same stored bytes in the same order as direct ones, so the
//   frame is the direct frame byte for byte (F32 and a quantised storage);
// - a strip's setup order holds every mesh triangle once with its winding (a rotation of it),
//   plus only degenerate joins;
// - the FIFO log of :draw=list holds one GX_CallDispList a draw whose list is one of the frame's
//   memory updates, 32-byte aligned and padded; read back (a second reader: fifo/stream_reader.h)
//   through the arrays the CP registers point at, its strip's vertices are the emulator's, in the
//   strip's order.
// Dolphin's judgement of the same frames is tests/dolphin_vertex_draw_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>

#include "core/error.h"
#include "gx/fifo/stream_reader.h"
#include "load/load_scene.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_budget.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/indexed_recording.h"
#include "paths/gx/object_draw.h"
#include "paths/gx/scene_draw_cost.h"
#include "paths/gx/scene_vertices.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

constexpr int kDrawWidth = 160, kDrawHeight = 120;

const Scene& draw_cubes() {
  static const Scene scene = load_scene(test::source_dir() / "scenes/coloured_cubes.json");
  return scene;
}

TEST(GxVertexDraw, TheDrawAxisRoundTripsAndABadValueIsOneLine) {
  EXPECT_EQ(parse_gx_variant("t=vertex:draw=direct"), parse_gx_variant("t=vertex"));
  for (const char* name : {"indexed", "strips", "list"}) {
    const std::string text = std::string("t=vertex:vtx=s16/auto:draw=") + name;
    const GxVariant v = parse_gx_variant(text);
    EXPECT_EQ(to_string(v), text);
    EXPECT_EQ(parse_gx_variant(to_string(v)), v);
  }
  for (const char* bad : {"t=vertex:draw=fans", "t=vertex:draw=list:draw=strips"}) {
    try {
      parse_gx_variant(bad);
      ADD_FAILURE() << bad << " parsed";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(bad), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
}

TEST(GxVertexDraw, IndexedTrianglesAreTheDirectFrameByteForByte) {
  for (const std::string storage : {"", ":vtx=s8/auto:nrm=s8:clr=rgba4:uv=s8/auto"}) {
    const Image direct =
        render_scene(draw_cubes(), "gx", "t=vertex" + storage, kDrawWidth, kDrawHeight);
    const Image indexed = render_scene(draw_cubes(), "gx", "t=vertex" + storage + ":draw=indexed",
                                       kDrawWidth, kDrawHeight);
    EXPECT_EQ(direct.rgba, indexed.rgba) << storage;
  }
}

// `t` rotated so its smallest vertex number comes first (a rotation keeps the winding).
glm::uvec3 rotated_to_smallest(glm::uvec3 t) {
  while (t.x > t.y || t.x > t.z) t = {t.y, t.z, t.x};
  return t;
}

TEST(GxVertexDraw, AStripSetsUpEveryMeshTriangleOnceWithItsWinding) {
  for (const SceneObject& o : draw_cubes().objects) {
    std::map<std::array<u32, 3>, int> expected, got;
    for (const glm::uvec3& t : o.mesh.triangles) {
      const glm::uvec3 r = rotated_to_smallest(t);
      ++expected[{r.x, r.y, r.z}];
    }
    const std::vector<glm::uvec3> strip = setup_order(o.mesh, GxVariant::Draw::Strips);
    EXPECT_EQ(strip, setup_order(o.mesh, GxVariant::Draw::List));
    size_t degenerate = 0;
    for (const glm::uvec3& t : strip) {
      if (t.x == t.y || t.y == t.z || t.x == t.z) {
        ++degenerate;
        continue;
      }
      const glm::uvec3 r = rotated_to_smallest(t);
      ++got[{r.x, r.y, r.z}];
    }
    EXPECT_EQ(got, expected);
    EXPECT_EQ(strip.size(), o.mesh.triangles.size() + degenerate);
    EXPECT_EQ(setup_order(o.mesh, GxVariant::Draw::Indexed), o.mesh.triangles);
  }
}

// The bytes of memory at `address`, `size` long, from the frame's updates.
std::vector<u8> log_memory_at(const fifo::FifoFrame& frame, u32 address, size_t size) {
  for (const fifo::MemoryUpdate& u : frame.updates)
    if (u.address <= address && address + size <= u.address + u.data.size())
      return {u.data.begin() + (address - u.address),
              u.data.begin() + (address - u.address) + static_cast<long>(size)};
  ADD_FAILURE() << "no memory update holds " << address << " + " << size;
  return {};
}

TEST(GxVertexDraw, TheDisplayListIsInTheLogsMemoryAndDrawsTheEmulatorsStrip) {
  const Scene& scene = draw_cubes();
  const GxVariant v = parse_gx_variant("t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:draw=list");
  const ScenePrograms programs = scene_programs_for(scene, v, "");
  const SceneView view = SceneView::of(scene);
  std::vector<VertexStream> streams;
  for (const SceneObject& o : scene.objects)
    streams.push_back(stored_vertex_stream(scene, o, view, v.storage, "test", true));
  std::vector<std::pair<size_t, size_t>> expected;  // (object, pass) in the frame's order
  for (const MaterialDraw& d : programs.draws(scene))
    for (size_t i : d.objects) expected.emplace_back(i, static_cast<size_t>(d.pass));
  const fifo::FifoLog log = fifo::record_frames(scene, {{v, &programs}}, {kDrawWidth, kDrawHeight});
  const fifo::FifoFrame& frame = log.frames.at(0);
  // The frame itself sends no vertex: each draw is a call.
  fifo::RegisterFile regs;
  const fifo::StreamEvents events = fifo::read_stream(frame.fifo, regs, "frame");
  EXPECT_TRUE(events.draws.empty());
  ASSERT_EQ(events.display_lists.size(), expected.size());
  // Each call again, with the registers as they stand at it: read the frame up to the call.
  size_t checked = 0;
  for (size_t k = 0; k < expected.size(); ++k) {
    const fifo::StreamCall& call = events.display_lists[k];
    EXPECT_EQ(call.address % 32, 0u);
    EXPECT_EQ(call.size % 32, 0u);
    EXPECT_GE(call.address, fifo::kVertexMemoryBase);
    fifo::RegisterFile r;
    fifo::read_stream({frame.fifo.begin(), frame.fifo.begin() + static_cast<long>(call.offset)}, r,
                      "frame");
    const std::vector<u8> list = log_memory_at(frame, call.address, call.size);
    const VertexLoader loader(unpack_vertex_inputs(r.cp[0x50], r.cp[0x60]),
                              unpack_vertex_format(r.cp[0x70], r.cp[0x80], r.cp[0x90]), "list");
    EXPECT_TRUE(loader.inputs().position == AttributeInput::Index8 ||
                loader.inputs().position == AttributeInput::Index16);
    VertexArrays arrays;
    std::vector<std::vector<u8>> held(kVertexArrays);
    for (int a = 0; a < kVertexArrays; ++a) {
      if (r.cp[0xb0 + a] == 0) continue;
      const auto i = static_cast<size_t>(a);
      // Up to the end of the update that holds the base: at most 255 elements of the stride.
      for (const fifo::MemoryUpdate& u : frame.updates)
        if (u.address == r.cp[0xa0 + a]) held[i] = u.data;
      arrays[i] = {held[i], r.cp[0xb0 + a]};
    }
    const auto [object, pass] = expected[k];
    const std::vector<u32> strip = sent_vertex_order(scene.objects[object].mesh, v.draw);
    std::vector<LoadedVertex> loaded;
    fifo::RegisterFile lr = r;
    fifo::read_stream(list, lr, "list", [&](const fifo::RegisterFile&, const fifo::StreamDraw& d) {
      EXPECT_EQ(d.primitive, fifo::kPrimitiveTriangleStrip);
      const auto part = loader.load(std::span(list).subspan(d.offset), d.count, arrays);
      loaded.insert(loaded.end(), part.begin(), part.end());
    });
    const VertexStream& s = streams[object];
    ASSERT_EQ(loaded.size(), strip.size());
    for (size_t n = 0; n < loaded.size(); ++n) {
      ASSERT_EQ(loaded[n].position, s.position[strip[n]]) << n;
      if (loader.inputs().normal != AttributeInput::None) {
        ASSERT_EQ(loaded[n].normal[0], s.normal[strip[n]]) << n;
      }
      if (loader.inputs().texcoord[0] != AttributeInput::None) {
        ASSERT_EQ(loaded[n].texcoord[0].x, s.t_per_light[pass][strip[n]]) << n;
      }
      ++checked;
    }
  }
  EXPECT_GT(checked, 0u);
}

// The budget of a variant's vertices (scene_draw_cost.h) is what its FIFO log sends, read back
// by the stream reader: the FIFO bytes (draws, GX_SetArray's CP loads, GX_CallDispList), the
// vertices the XF gets (the lists' draws too) and the triangles set up (a strip's n - 2).
TEST(GxVertexDraw, TheVariantsBudgetIsWhatItsFifoLogSends) {
  const Scene& scene = draw_cubes();
  for (const char* draw : {"direct", "indexed", "strips", "list"}) {
    for (const std::string storage : {"", ":vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto"}) {
      const GxVariant v = parse_gx_variant("t=vertex" + storage + ":draw=" + draw);
      const ScenePrograms programs = scene_programs_for(scene, v, "");
      const SceneDrawCost cost = scene_draw_cost(scene, programs, v.storage, v.draw, "test");
      const fifo::FifoLog log =
          fifo::record_frames(scene, {{v, &programs}}, {kDrawWidth, kDrawHeight});
      const fifo::FifoFrame& frame = log.frames.at(0);
      size_t fifo_bytes = 0, vertices = 0, triangles = 0, list_bytes = 0;
      auto count = [&](const fifo::StreamDraw& d) {
        vertices += d.count;
        triangles += d.primitive == fifo::kPrimitiveTriangleStrip ? d.count - 2 : d.count / 3;
      };
      fifo::RegisterFile regs;
      const fifo::StreamEvents ev = fifo::read_stream(frame.fifo, regs, "frame");
      for (const fifo::StreamDraw& d : ev.draws) {
        count(d);
        fifo_bytes += 3 + d.count * d.vertex_size;
      }
      fifo_bytes += 6 * ev.array_loads + 9 * ev.display_lists.size();
      for (const fifo::StreamCall& call : ev.display_lists) {
        fifo::RegisterFile r;
        fifo::read_stream({frame.fifo.begin(), frame.fifo.begin() + static_cast<long>(call.offset)},
                          r, "frame");
        const fifo::StreamEvents in_list =
            fifo::read_stream(log_memory_at(frame, call.address, call.size), r, "list");
        for (const fifo::StreamDraw& d : in_list.draws) count(d);
        list_bytes += call.size;
      }
      const std::string name = to_string(v);
      EXPECT_EQ(cost.draw.fifo_bytes, fifo_bytes) << name;
      EXPECT_EQ(cost.draw.vertices, vertices) << name;
      EXPECT_EQ(cost.draw.triangles, triangles) << name;
      // Lists are counted once per object and descriptor; the log calls one per pass.
      EXPECT_LE(cost.draw.display_list_bytes, list_bytes) << name;
      EXPECT_EQ(cost.draw.display_list_bytes > 0, std::string(draw) == "list") << name;
      EXPECT_EQ(cost.draw.array_bytes > 0, std::string(draw) != "direct") << name;
    }
  }
}

// The budget's details for a variant: its own figures beside the F32 immediate and the stored
// display list ones; the default variant's are the F32 immediate figures, a stored display
// list's those of the same storage as a list.
TEST(GxVertexDraw, TheBudgetGivesTheVariantsOwnFigures) {
  auto details = [](const std::string& variant) {
    std::map<std::string, int> out;
    for (const budget::Detail& d : gx_budget_scene(draw_cubes(), variant, "").details)
      if (d.number) out[d.key] = *d.number;
    return out;
  };
  const auto f32 = details("t=vertex");
  for (const char* k : {"vertex_bytes", "fifo_bytes", "xf_vertices", "triangles"})
    EXPECT_EQ(f32.at(k), f32.at(std::string("f32_") + k)) << k;
  EXPECT_EQ(f32.at("array_bytes"), 0);
  EXPECT_EQ(f32.at("display_list_bytes"), 0);
  const auto list = details("t=vertex:vtx=s16:nrm=s8:clr=rgb565:uv=s16:draw=list");
  for (const char* k : {"vertex_bytes", "array_bytes", "refreshed_array_bytes",
                        "display_list_bytes", "fifo_bytes", "xf_vertices", "triangles"})
    EXPECT_EQ(list.at(k), list.at(std::string("stored_") + k)) << k;
}

// A cube of 24 vertices (4 a face, so each face has its own normal) and 12 triangles, drawn
// once with positions and normals only: its costs in closed form.
TEST(GxVertexDraw, ACubesCostsAreTheirClosedForms) {
  TriangleMesh cube;
  const int axes[6][3] = {{0, 1, 2}, {0, 1, 2}, {1, 2, 0}, {1, 2, 0}, {2, 0, 1}, {2, 0, 1}};
  for (int f = 0; f < 6; ++f) {
    const double side = f % 2 ? 1.0 : -1.0;
    const u32 base = static_cast<u32>(cube.positions.size());
    for (int k = 0; k < 4; ++k) {
      glm::dvec3 p(0.0), n(0.0);
      p[axes[f][2]] = side;
      p[axes[f][0]] = (k == 1 || k == 2) ? 1.0 : -1.0;
      p[axes[f][1]] = k >= 2 ? 1.0 : -1.0;
      n[axes[f][2]] = side;
      cube.positions.push_back(p);
      cube.normals.push_back(n);
    }
    cube.triangles.emplace_back(base, base + 1, base + 2);
    cube.triangles.emplace_back(base, base + 2, base + 3);
  }
  // Positions s16 (6 bytes) and normals s8 (3 bytes) stored; the arrays hold each distinct
  // element once: 8 corners, 6 normals.
  VertexAttributeData data;
  for (const glm::dvec3& p : cube.positions) data.position.emplace_back(p);
  for (const glm::dvec3& n : cube.normals) data.normal.emplace_back(n);
  const VertexStorage storage = parse_vertex_storage("vtx=s16/8,nrm=s8", "test");
  const VertexAttributeFormat format = storage_format(storage, data, "test");
  const IndexedArrays arrays = index_attributes(quantise_attributes(data, format), "test");
  EXPECT_EQ(arrays.bytes[kArrayPosition].size(), 8u * 6);  // 8 distinct corners, 3 x s16
  EXPECT_EQ(arrays.bytes[kArrayNormal].size(), 6u * 3);    // 6 distinct normals, 3 x s8
  const size_t index_bytes = VertexLoader(indexed_inputs(arrays), format, "t").vertex_size();
  EXPECT_EQ(index_bytes, 2u);  // two GX_INDEX8
  const DrawCost direct = immediate_list_cost(12, 6 + 3);
  EXPECT_EQ(direct.fifo_bytes, 3u + 36 * 9);
  const DrawCost indexed = indexed_cost(immediate_list_cost(12, index_bytes), arrays);
  EXPECT_EQ(indexed.fifo_bytes, 3u + 36 * 2 + 2 * 2 * 6);
  EXPECT_EQ(indexed.array_bytes, 64u + 32);  // 48 and 18 bytes in whole 32-byte lines
  EXPECT_EQ(indexed.vertices, 36u);
  const std::vector<u32> strip = sent_vertex_order(cube, GxVariant::Draw::Strips);
  const DrawCost listed = display_list_strip_cost(strip.size(), index_bytes, arrays);
  EXPECT_EQ(listed.fifo_bytes, 9u + 2 * 2 * 6);
  EXPECT_EQ(listed.vertices, strip.size());
  EXPECT_EQ(listed.triangles, strip.size() - 2);
  EXPECT_EQ(listed.display_list_bytes, (3 + 2 * strip.size() + 31) / 32 * 32);
  // A strip of 12 triangles needs at least 14 vertices, at most a list's 36 (with joins).
  EXPECT_GE(strip.size(), 14u);
  EXPECT_LT(strip.size(), 36u);
}

}  // namespace
}  // namespace lt::gx
