// A module of a stored variant (issue 46: `export gx --variant
// lobe=xf-spec:view=object:vtx=s16/auto :nrm=s8:clr=rgb565:draw=list --format module`) sends what
// ltrender's FIFO log sends, frame after frame. The module is compiled on the host
// (tests/gx_module_host/), ltrender_stored_init builds its display lists once, and along the camera
// path its pass functions drive the emulator (the frame must be the variant's own, every channel)
// while its draw (ltrender_draw_stored) is recorded: every matrix it loads (computed in its C from
// the camera, ltr_object_matrices) must be in the emulator's FIFO log of that frame as the very
// bytes, each object's descriptor and format the VCD and VAT the log loads for it, every array it
// points the CP at and every display list it calls a block of the log's memory (and every block one
// of them), and every draw it sends in the log's FIFO as the very bytes. Under t=vertex the arrays
// include each pass's t, which the module computes (ltr_fill_t over the game's world-space meshes),
// stores and flushes every frame (ltr_stored_write_t): the log's t blocks of that frame, byte for
// byte, under the display lists built once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <set>

#include "gx/fifo/command_stream.h"
#include "gx/fifo/cp_registers.h"
#include "gx/fifo/fifo_log.h"
#include "gx/vertex_format.h"
#include "gx_module_host/host_module.h"
#include "load/load_scene.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/indexed_recording.h"
#include "paths/gx/module/module_exporter.h"
#include "render/camera_path.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx::test_module {
namespace {

constexpr int kStoredFrameSize = 96;
// Three frames of the path: the camera and lights move between them.
constexpr int kStoredFramesChecked[] = {0, 3, 6};

struct DrawSegment {
  char kind = 0;
  std::vector<u8> bytes;
};

std::vector<DrawSegment> draw_segments(const u8* p, u32 length) {
  std::vector<DrawSegment> out;
  for (u32 at = 0; at + 5 <= length;) {
    u32 n = 0;
    std::memcpy(&n, p + at + 1, 4);
    out.push_back({static_cast<char>(p[at]), std::vector<u8>(p + at + 5, p + at + 5 + n)});
    at += 5 + n;
  }
  return out;
}

bool holds_bytes(const std::vector<u8>& haystack, const std::vector<u8>& needle) {
  return !needle.empty() && std::search(haystack.begin(), haystack.end(), needle.begin(),
                                        needle.end()) != haystack.end();
}

u32 big_endian_word(const std::vector<u8>& b, size_t at) {
  return static_cast<u32>(b[at]) << 24 | static_cast<u32>(b[at + 1]) << 16 |
         static_cast<u32>(b[at + 2]) << 8 | b[at + 3];
}

// One object's GX_SetVtxDesc calls ('V': attribute, index type; after its GX_ClearVtxDesc) and
// GX_SetVtxAttrFmt calls ('F': attribute, count, type, fraction) against the CP loads the log
// sends for it (indexed_recording.cpp draw_indexed_object): the descriptor as the VCD pair, and
// right after it (past an NBT's XF vertex specs) VAT A, B, C of the variant's vertex format (`vat`,
// :vat=N: CP 0x70 + N ..) holding each of those attributes as the module declares it.
void expect_object_format(const std::vector<u8>& fifo_bytes, const std::vector<DrawSegment>& desc,
                          const std::vector<DrawSegment>& fmt, int vat_number,
                          const std::string& at) {
  // GX_VA_POS 9, NRM 10, CLR0 11, CLR1 12, TEX0..7 13..20; GX_INDEX8/16 are the CP's 2 and 3
  // [OGC gx.h L82-92] [DHW CPMemory.h VertexComponentFormat].
  VertexInputs in;
  for (const DrawSegment& g : desc) {
    const auto input = static_cast<AttributeInput>(g.bytes[1]);
    const int attribute = g.bytes[0];
    if (attribute == 9) in.position = input;
    if (attribute == 10 || attribute == 25) in.normal = input;  // GX_VA_NRM, GX_VA_NBT
    if (attribute == 11 || attribute == 12) in.color[static_cast<size_t>(attribute - 11)] = input;
    if (attribute >= 13 && attribute <= 20)
      in.texcoord[static_cast<size_t>(attribute - 13)] = input;
  }
  const std::array<u32, 2> vcd = pack_vertex_inputs(in);
  fifo::CommandStream loads;
  loads.load_cp(fifo::cp::kVcdLow, vcd[0]);
  loads.load_cp(fifo::cp::kVcdHigh, vcd[1]);
  const std::vector<u8> want = loads.bytes();
  bool matched = false;
  for (auto it = std::search(fifo_bytes.begin(), fifo_bytes.end(), want.begin(), want.end());
       it != fifo_bytes.end() && !matched;
       it = std::search(it + 1, fifo_bytes.end(), want.begin(), want.end())) {
    size_t vat = static_cast<size_t>(it - fifo_bytes.begin()) + want.size();
    // An NBT's XF 0x1008 (two normals) comes between, as libogc's __GX_SetVCD sends it: one XF
    // load of one word, 9 bytes (indexed_recording.cpp).
    if (vat < fifo_bytes.size() && fifo_bytes[vat] == 0x10) vat += 9;
    if (vat + 18 > fifo_bytes.size() || fifo_bytes[vat + 1] != fifo::cp::kVatA + vat_number)
      continue;
    const VertexAttributeFormat f = unpack_vertex_format(big_endian_word(fifo_bytes, vat + 2),
                                                         big_endian_word(fifo_bytes, vat + 8),
                                                         big_endian_word(fifo_bytes, vat + 14));
    bool all = true;
    for (const DrawSegment& g : fmt) {
      const int attribute = g.bytes[0], count = g.bytes[1], type = g.bytes[2], frac = g.bytes[3];
      if (attribute == 9)
        all = all && static_cast<int>(f.position.type) == type && f.position.frac == frac;
      else if (attribute == 10 || attribute == 25)  // GX_NRM_XYZ 0, GX_NRM_NBT 1, NBT3 2
        all = all && static_cast<int>(f.normal.type) == type && f.normal.nbt == (count > 0) &&
              f.normal.index3 == (count == 2);
      else if (attribute == 11)
        all = all && static_cast<int>(f.color[0].type) == type && f.color[0].alpha == (count == 1);
      else {
        const CoordinateFormat& c = f.texcoord[static_cast<size_t>(attribute - 13)];
        all =
            all && c.components == count + 1 && static_cast<int>(c.type) == type && c.frac == frac;
      }
    }
    matched = all;
  }
  EXPECT_TRUE(matched) << at << ": an object's descriptor and format the log does not load";
}

struct StoredCase {
  std::string scene, variant;
};
void PrintTo(const StoredCase& c, std::ostream* out) {
  *out << c.scene << " --variant " << c.variant;
}

class GxModuleStored : public ::testing::TestWithParam<StoredCase> {};

TEST_P(GxModuleStored, SendsTheEmulatorsMatricesArraysListsAndDrawsAlongAPath) {
  Scene base = load_scene(test::source_dir() / GetParam().scene);
  make_float(base);
  const GxVariant variant = parse_gx_variant(GetParam().variant);
  test::TempDir dir;
  const HostModule host(dir, export_module(base, variant, GetParam().scene));
  ASSERT_TRUE(host.compiled) << host.compiler_output;
  auto* init = host.get<VoidFn>("ltrender_stored_init");
  using DrawFn =
      void(const ltr_view*, const ltr_light[], const ltr_mesh[], ltr_pass_state* const[]);
  auto* draw = host.get<DrawFn>("ltrender_draw_stored");
  using BeginDrawsFn = void();
  using DrawsFn = const u8*(u32*);
  auto* begin_draws = host.get<BeginDrawsFn>("ltr_host_draws_begin");
  auto* recorded = host.get<DrawsFn>("ltr_host_draws");
  ASSERT_TRUE(init && draw && begin_draws && recorded);
  init();
  const ScenePlan plan = plan_scene(base, variant);
  GxVariant undeclared = variant;
  undeclared.storage = VertexStorage{};
  size_t lists_called = 0;
  std::map<int, std::set<std::vector<u8>>> t_blocks;  // by frame
  bool sends_t = false;
  for (const MaterialPlan& m : plan.materials)
    for (const PassPlan& p : m.passes) sends_t = sends_t || p.vertex.t;
  for (int k : kStoredFramesChecked) {
    const Scene s = scene_on_camera_path(base, k);
    const std::string at = GetParam().scene + " frame " + std::to_string(k);
    ltr_view view{};
    std::vector<std::vector<ltr_pass_state>> states;
    std::vector<ltr_light> lights;
    const std::string text = drive_frame(
        host, plan, s,
        [&](const MaterialFrame& f, const ltr_view& v, const std::vector<ltr_light>& l) {
          view = v;
          lights = l;
          states.push_back(f.states);
        });
    ASSERT_FALSE(text.empty()) << at;
    // The pass functions drive the emulator to the variant's own frame: they declare the
    // storage (with the fraction every object takes), so the variant given with them keeps only
    // its other axes (program_storage.h declared_variant).
    const fs::path file = dir / ("frame" + std::to_string(k) + ".c");
    test::write_file(file, text);
    const Image direct =
        render_scene(s, "gx", GetParam().variant, kStoredFrameSize, kStoredFrameSize);
    const Image driven = render_scene(s, "gx", to_string(undeclared), kStoredFrameSize,
                                      kStoredFrameSize, {file.string()});
    EXPECT_TRUE(direct.rgba == driven.rgba) << at << ": the module-driven frame differs";
    // The draw, recorded.
    std::vector<ltr_pass_state*> state_of(states.size());
    for (size_t m = 0; m < states.size(); ++m) state_of[m] = states[m].data();
    // Every object's world-space mesh, as the game gives it to the setups: a pass that sends t
    // computes it there (ltr_fill_t).
    std::vector<MeshArrays> objects;
    for (const SceneObject& o : s.objects) objects.push_back(arrays_of(o));
    std::vector<ltr_mesh> meshes;
    for (MeshArrays& a : objects) {
      a.mesh.positions = a.positions.data();
      a.mesh.normals = a.normals.data();
      meshes.push_back(a.mesh);
    }
    begin_draws();
    draw(&view, lights.data(), meshes.data(), state_of.data());
    u32 length = 0;
    const u8* bytes = recorded(&length);
    const std::vector<DrawSegment> sent = draw_segments(bytes, length);
    // The emulator's FIFO log of the same frame (its own programs).
    const ScenePrograms programs = scene_programs_for(s, variant, "");
    const fifo::FifoLog log =
        fifo::record_frames(s, {{variant, &programs, &s}}, {kStoredFrameSize, kStoredFrameSize});
    ASSERT_EQ(log.frames.size(), 1u);
    const fifo::FifoFrame& frame = log.frames[0];
    std::set<std::vector<u8>> blocks, module_blocks;
    for (const fifo::MemoryUpdate& u : frame.updates)
      if (u.type == fifo::kMemoryUpdateVertexStream) blocks.insert(u.data);
    size_t matrices = 0, draws = 0, formats = 0, t_arrays = 0;
    std::vector<DrawSegment> desc, fmt;  // the object's, after its matrices
    bool object_format = false;
    for (const DrawSegment& g : sent) {
      if (object_format && g.kind == 'A') {
        ++formats;
        expect_object_format(frame.fifo, desc, fmt, variant.vat, at);
        object_format = false;
      }
      if (g.kind == 'N') {
        object_format = true;
        desc.clear();
        fmt.clear();
      }
      if (object_format && g.kind == 'V') desc.push_back(g);
      if (object_format && g.kind == 'F') fmt.push_back(g);
      if (g.kind == 'P' || g.kind == 'N') {
        ++matrices;
        EXPECT_TRUE(holds_bytes(frame.fifo, g.bytes)) << at << ": a matrix the log does not load";
      } else if (g.kind == 'D') {
        ++draws;
        EXPECT_TRUE(holds_bytes(frame.fifo, g.bytes)) << at << ": a draw the log does not send";
      } else if (g.kind == 'A') {
        module_blocks.insert(std::vector<u8>(g.bytes.begin() + 2, g.bytes.end()));
        // GX_VA_TEX0 (13) of a variant that sends t: a t array, written by the CPU this frame.
        if (g.bytes[0] == 13 && sends_t) {
          ++t_arrays;
          t_blocks[k].insert(std::vector<u8>(g.bytes.begin() + 2, g.bytes.end()));
        }
      } else if (g.kind == 'L') {
        ++lists_called;
        module_blocks.insert(g.bytes);
      }
    }
    EXPECT_GT(matrices, 0u) << at;
    EXPECT_EQ(2 * formats, matrices) << at << ": an object drawn without its format";
    EXPECT_EQ(draws > 0, variant.draw != GxVariant::Draw::List) << at;
    EXPECT_EQ(t_arrays > 0, sends_t) << at << ": " << t_arrays << " t arrays set";
    EXPECT_TRUE(module_blocks == blocks)
        << at << ": the module's arrays and lists (" << module_blocks.size()
        << ") are not the log's memory blocks (" << blocks.size() << ")";
  }
  EXPECT_EQ(lists_called > 0, variant.draw == GxVariant::Draw::List);
  // The camera and lights move along the path: the t the CPU writes is not the same each frame.
  if (sends_t) EXPECT_NE(t_blocks[kStoredFramesChecked[0]], t_blocks[kStoredFramesChecked[1]]);
}

// Four demo scenes: the blob's one mesh as a display list with NBT3 normals (three indices a
// normal), coloured_cubes' two cubes (rotated, scaled, moved: each its own matrices) as strips
// sent every frame in GX_VTXFMT5 (the module's LTRENDER_VTXFMT: its VAT and draw commands must be
// the log's), and albedo_checker's map (its UVs an array of their own) as a display list, all
// lobe=xf-spec:view=object (no per-vertex t); and thin_vs_thick's two slabs with t=vertex: each
// pass's t computed by the CPU (ltr_fill_t), stored as s16 with the fraction the frame's t allows
// and flushed every frame into arrays the lists, built once, index.
const StoredCase kStoredCases[] = {
    {"scenes/three_point_blob.json",
     "lobe=xf-spec:view=object:vtx=s16/auto:nrm=s8/nbt3:clr=rgb565:draw=list"},
    {"scenes/coloured_cubes.json",
     "lobe=xf-spec:view=object:vtx=s16/auto:nrm=s8:clr=rgb565:draw=strips:vat=5"},
    {"scenes/albedo_checker.json",
     "lobe=xf-spec:view=object:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list"},
    {"scenes/thin_vs_thick.json", "t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list"},
};

INSTANTIATE_TEST_SUITE_P(StoredScenes, GxModuleStored, ::testing::ValuesIn(kStoredCases),
                         [](const auto& info) {
                           return test::test_param_name(info.param.scene + "_" +
                                                        info.param.variant);
                         });

// A storage sent directly (a stored module indexes its mesh): one line naming the variant, exit
// 2, no file.
TEST(GxModuleExport, RefusesAStorageSentDirectly) {
  test::TempDir dir;
  const fs::path out = dir / "m.c";
  for (const char* variant : {"t=vertex:vtx=s16/8", "lobe=xf-spec:view=object:vtx=s16/8"}) {
    const test::RunResult r =
        test::run_ltrender("export gx " + (test::source_dir() / "scenes/baked_blob.json").string() +
                           " --variant " + variant + " --format module -o " + out.string());
    EXPECT_EQ(r.exit_code, 2) << variant;
    EXPECT_NE(r.err.find("--format module"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(out));
  }
}

}  // namespace
}  // namespace lt::gx::test_module
