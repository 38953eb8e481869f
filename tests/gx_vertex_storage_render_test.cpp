// The gx path renders through the vertex storage (issue 46 step 2): the variant's :vtx= :nrm=
// :clr= :uv= axes store each object's mesh as a port does (in its own coordinates, quantised)
// and the emulator lights and rasterises what the console's vertex loader gives back.
// - the default variant and an explicit all-f32 storage are the same variant and the same frame;
// - every position the emulator receives is the object-space position rounded to the format's
//   step (computed here with std::round, not the quantiser), within half a step of it, and the
//   object's matrix takes it to where the F32 stream has it (to the step);
// - a fine storage (s16/auto) moves a few pixels by little, a coarse one (s8/auto) moves more;
// - the FIFO log's draws, read back through the VCD and VAT they declare by the vertex loader,
//   are the vertices the emulator received, under the object's matrices;
// - a bad value names the variant key.
// Dolphin's judgement of the same frames is tests/dolphin_vertex_storage_test.cpp.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>

#include "core/error.h"
#include "gx/fifo/stream_reader.h"
#include "gx/fifo/xf_registers.h"
#include "gx/transform_unit.h"
#include "load/load_scene.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/scene_vertices.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

constexpr int kFrameWidth = 160, kFrameHeight = 120;

const Scene& cubes() {
  static const Scene scene = load_scene(test::source_dir() / "scenes/coloured_cubes.json");
  return scene;
}

TEST(GxVertexStorageRender, AnExplicitF32StorageIsTheDefaultFrameByteForByte) {
  const std::string f32 = "t=vertex:vtx=f32:nrm=f32:clr=rgba8:uv=f32";
  EXPECT_EQ(parse_gx_variant(f32), parse_gx_variant("t=vertex"));
  EXPECT_EQ(to_string(parse_gx_variant(f32)), "t=vertex");
  const Image a = render_scene(cubes(), "gx", "t=vertex", kFrameWidth, kFrameHeight);
  const Image b = render_scene(cubes(), "gx", f32, kFrameWidth, kFrameHeight);
  ASSERT_EQ(a.rgba.size(), b.rgba.size());
  EXPECT_EQ(a.rgba, b.rgba);
}

TEST(GxVertexStorageRender, TheVariantNamesEachStoredAttributeAndRoundTrips) {
  const GxVariant v = parse_gx_variant("t=vertex:nrm=s8:vtx=s16:clr=rgb565:uv=u16/12");
  EXPECT_EQ(to_string(v), "t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=u16/12");
  EXPECT_EQ(parse_gx_variant(to_string(v)), v);
  EXPECT_EQ(v.storage.position.type, ComponentType::S16);
  EXPECT_TRUE(v.storage.position.auto_frac);
  EXPECT_EQ(v.storage.texcoord.frac, 12);
}

TEST(GxVertexStorageRender, ABadStorageValueIsOneLineNamingTheVariantKey) {
  for (const char* bad : {"t=vertex:vtx=s17", "t=vertex:nrm=u8", "t=vertex:clr=rgb555",
                          "t=vertex:uv=s16/32", "t=vertex:vtx=s16:vtx=s8"}) {
    try {
      parse_gx_variant(bad);
      ADD_FAILURE() << bad << " parsed";
    } catch (const InputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find(bad), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  }
  // A fraction the mesh's positions overflow (the cubes reach past 1; s8/7 holds -1 .. 0.99).
  try {
    render_scene(cubes(), "gx", "t=vertex:vtx=s8/7", kFrameWidth, kFrameHeight);
    ADD_FAILURE() << "s8/7 rendered";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "vtx") << e.what();
    EXPECT_NE(std::string(e.what()).find("s8/7 holds"), std::string::npos) << e.what();
  }
}

// The largest fraction s16 holds `lo`..`hi` at, worked out from the range: 2^f * max|v| must
// round within -32768..32767.
int s16_auto_fraction(const std::vector<glm::vec3>& values) {
  double far = 0;
  for (const glm::vec3& p : values)
    for (int c = 0; c < 3; ++c) far = std::max(far, std::abs(static_cast<double>(p[c])));
  int f = 31;
  while (f > 0 && std::round(far * std::ldexp(1.0, f)) > 32767) --f;
  return f;
}

TEST(GxVertexStorageRender, TheEmulatorReceivesEachPositionRoundedToItsStepInObjectSpace) {
  const Scene& scene = cubes();
  const SceneView view = SceneView::of(scene);
  VertexStorage storage;
  storage.position = {ComponentType::S16, 0, true};
  for (const SceneObject& o : scene.objects) {
    const ObjectSpaceMesh mesh = object_space_mesh(o, view);
    const VertexStream f32 = make_vertex_stream(scene, o, view);
    const VertexStream s = stored_vertex_stream(scene, o, view, storage, "test");
    ASSERT_TRUE(s.object_matrices);
    ASSERT_EQ(s.position.size(), mesh.position.size());
    const int frac = s16_auto_fraction(mesh.position);
    const double step = std::ldexp(1.0, -frac);
    for (size_t v = 0; v < s.position.size(); ++v) {
      for (int c = 0; c < 3; ++c) {
        const double x = mesh.position[v][c];
        const double expected = std::round(x / step) * step;  // halves away from zero
        ASSERT_EQ(static_cast<double>(s.position[v][c]), expected) << v << "," << c;
        ASSERT_LE(std::abs(expected - x), step / 2);
      }
      // The XF's eye position from the stored position, and the F32 stream's eye position
      // within what the step explains (the transform scales by 0.8; float slack).
      const glm::vec3 eye = eye_position(s.object_matrices->position, s.position[v]);
      ASSERT_EQ(s.eye_position[v], eye);
      for (int c = 0; c < 3; ++c)
        ASSERT_NEAR(eye[c], f32.eye_position[v][c], 0.8 * step * std::sqrt(3.0) / 2 + 1e-4);
      // F32 normals, colours and t are untouched by a position-only storage (up to the object
      // space round trip of the normal).
      EXPECT_EQ(s.color[v], f32.color[v]);
    }
    ASSERT_EQ(s.t_per_light.size(), f32.t_per_light.size());
    for (size_t l = 0; l < s.t_per_light.size(); ++l)
      EXPECT_EQ(s.t_per_light[l], f32.t_per_light[l]);
  }
}

TEST(GxVertexStorageRender, TheFifoLogsStoredBytesLoadAsTheEmulatorsVertices) {
  const Scene& scene = cubes();
  const GxVariant v = parse_gx_variant("t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s8/auto");
  const ScenePrograms programs = scene_programs_for(scene, v, "");
  const SceneView view = SceneView::of(scene);
  std::vector<VertexStream> streams;
  for (const SceneObject& o : scene.objects)
    streams.push_back(stored_vertex_stream(scene, o, view, v.storage, "test"));
  // The draws in the order the frame sends them: (object, pass), one draw each (small meshes).
  std::vector<std::pair<size_t, size_t>> expected;
  for (const MaterialDraw& d : programs.draws(scene))
    for (size_t i : d.objects) expected.emplace_back(i, static_cast<size_t>(d.pass));
  const fifo::FifoLog log =
      fifo::record_frames(scene, {{v, &programs}}, {kFrameWidth, kFrameHeight});
  const std::vector<u8>& bytes = log.frames.at(0).fifo;
  size_t draw = 0, checked = 0;
  fifo::RegisterFile regs;
  fifo::read_stream(
      bytes, regs, "frame", [&](const fifo::RegisterFile& r, const fifo::StreamDraw& d) {
        ASSERT_LT(draw, expected.size());
        const auto [object, pass] = expected[draw++];
        const VertexStream& s = streams[object];
        const VertexLoader loader(unpack_vertex_inputs(r.cp[0x50], r.cp[0x60]),
                                  unpack_vertex_format(r.cp[0x70], r.cp[0x80], r.cp[0x90]),
                                  "frame");
        ASSERT_EQ(loader.vertex_size(), d.vertex_size);
        EXPECT_EQ(loader.format().position.type, ComponentType::S16);
        EXPECT_EQ(loader.format().normal.type, ComponentType::S8);
        EXPECT_EQ(loader.format().color[0].type, ColorType::Rgb565);
        EXPECT_TRUE(loader.format().byte_dequant);
        for (size_t k = 0; k < 12; ++k)
          EXPECT_EQ(std::bit_cast<float>(r.xf_memory[fifo::xf::kPositionMatrices + k]),
                    s.object_matrices->position[k]);
        const std::vector<LoadedVertex> loaded =
            loader.load(std::span(bytes).subspan(d.offset), d.count, VertexArrays{});
        const TriangleMesh& mesh = scene.objects[object].mesh;
        ASSERT_EQ(loaded.size(), 3 * mesh.triangles.size());
        for (size_t k = 0; k < loaded.size(); ++k) {
          const u32 i = mesh.triangles[k / 3][static_cast<int>(k % 3)];
          ASSERT_EQ(loaded[k].position, s.position[i]) << k;
          if (loader.inputs().normal != AttributeInput::None) {
            ASSERT_EQ(loaded[k].normal[0], s.normal[i]) << k;
          }
          if (loader.inputs().color[0] != AttributeInput::None) {
            ASSERT_EQ(loaded[k].color[0], s.color[i]) << k;
          }
          if (loader.inputs().texcoord[0] != AttributeInput::None) {
            ASSERT_EQ(loaded[k].texcoord[0].x, s.t_per_light[pass][i]) << k;
          }
          ++checked;
        }
      });
  EXPECT_EQ(draw, expected.size());
  EXPECT_GT(checked, 0u);
}

TEST(GxVertexStorageRender, AFineStorageMovesLittleAndACoarseOneMore) {
  const Image f32 = render_scene(cubes(), "gx", "t=vertex", kFrameWidth, kFrameHeight);
  const test::PictureDifference fine = test::picture_difference(
      f32, render_scene(cubes(), "gx", "t=vertex:vtx=s16/auto:nrm=s16:uv=s16/auto", kFrameWidth,
                        kFrameHeight));
  const test::PictureDifference coarse = test::picture_difference(
      f32, render_scene(cubes(), "gx", "t=vertex:vtx=s8/auto:nrm=s8:clr=rgba4:uv=s8/auto",
                        kFrameWidth, kFrameHeight));
  std::printf("fine: %zu pixels, max %d LSB; coarse: %zu pixels, max %d LSB\n", fine.differ,
              fine.max, coarse.differ, coarse.max);
  // s16 positions move a vertex by at most 2^-15 object units, far under a pixel here: the few
  // pixels that differ are edge and shading pixels a rounding flips (measured: 7 of 19,200).
  EXPECT_LT(fine.differ, kFrameWidth * kFrameHeight / 100u);
  EXPECT_GT(coarse.differ, 4 * fine.differ);
  EXPECT_GE(coarse.max, fine.max);
}

}  // namespace
}  // namespace lt::gx
