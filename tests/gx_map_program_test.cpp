// Program files with a second texture map (the gx path's thickness-map extension of gx.md §1):
// a GX_TEXMAP1 texture in RGBA8, RGB565 or I8, sampled at the mesh's UV sent as a GX_TEX_ST
// texture coordinate through GX_IDENTITY, renders the texels the tile order and the decode say,
// the right way up (v = 0 at the bottom, gx_state.h); the program checks refuse what the stream
// cannot feed. One process per test (GL).
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "gx/texture_unit.h"
#include "gx_program_util.h"
#include "load/load_scene.h"
#include "render/session.h"
#include "scene/scene_parse.h"
#include "test_util.h"

namespace lt {
namespace {

// A quad filling the middle of a 64x48 image, seen head-on; with `uvs`, each vertex's UV is its
// position mapped from [-1, 1] to [0, 1] (u right, v up).
Scene uv_quad_scene(const test::TempDir& dir, bool uvs) {
  test::write_file(dir / "quad.obj", test::quad_obj());
  const std::string text = R"({
    "image": { "width": 64, "height": 48 },
    "camera": { "eye": [0, 0, 3], "target": [0, 0, 0], "up": [0, 1, 0], "fov_y_deg": 50 },
    "materials": { "m": { "albedo": [1, 1, 1] } },
    "lights": [ { "type": "directional", "direction": [0, 0, -1], "intensity": 1 } ],
    "objects": [ { "mesh": "quad.obj", "material": "m" } ] })";
  Scene scene = load_scene(parse_scene(text, (dir / "quad.json").string(), dir.path()));
  if (uvs) {
    TriangleMesh& m = scene.objects[0].mesh;
    m.uvs.clear();
    for (const glm::dvec3& p : m.positions) m.uvs.emplace_back((p.x + 1) / 2, (p.y + 1) / 2);
  }
  return scene;
}

// One stage showing GX_TEXMAP1's texel (GX_REPLACE: TEXC, TEXA) at the UV in GX_VA_TEX0, every
// face drawn (GX_Init's GX_CULL_BACK would cull the quad, wound as GL's front face).
std::string map_program(const std::vector<gx::u8>& tiles, const std::string& format) {
  return test::c_byte_array("map", tiles) + R"(GXTexObj tex;
GX_SetCullMode(GX_CULL_NONE);
GX_ClearVtxDesc();
GX_SetVtxDesc(GX_VA_POS, GX_DIRECT);
GX_SetVtxDesc(GX_VA_TEX0, GX_DIRECT);
GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_POS, GX_POS_XYZ, GX_F32, 0);
GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_TEX0, GX_TEX_ST, GX_F32, 0);
GX_SetNumChans(0);
GX_SetNumTexGens(1);
GX_SetTexCoordGen(GX_TEXCOORD0, GX_TG_MTX2x4, GX_TG_TEX0, GX_IDENTITY);
GX_InitTexObj(&tex, map, 2, 2, )" +
         format + R"(, GX_CLAMP, GX_CLAMP, GX_FALSE);
GX_LoadTexObj(&tex, GX_TEXMAP1);
GX_SetNumTevStages(1);
GX_SetTevOrder(GX_TEVSTAGE0, GX_TEXCOORD0, GX_TEXMAP1, GX_COLORNULL);
GX_SetTevOp(GX_TEVSTAGE0, GX_REPLACE);
)";
}

std::array<int, 3> pixel(const Image& img, int x, int y) {
  const float* p = img.at(x, y);
  return {static_cast<int>(std::lround(p[0] * 255)), static_cast<int>(std::lround(p[1] * 255)),
          static_cast<int>(std::lround(p[2] * 255))};
}

// The four corner pixels of the covered quad: (left, bottom), (right, bottom), (left, top),
// (right, top) in the image (row 0 at the top). Their UVs lie within a quarter of the map of its
// corners, beyond the texel centres of a 2 x 2 map, so the clamped bilinear gives each corner's
// texel exactly.
std::array<std::array<int, 3>, 4> corners(const Image& img) {
  int x0 = img.width, x1 = -1, y0 = img.height, y1 = -1;
  for (int y = 0; y < img.height; ++y) {
    for (int x = 0; x < img.width; ++x) {
      if (img.at(x, y)[3] < 0.5f) continue;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
    }
  }
  EXPECT_GT(x1 - x0, 10);
  return {pixel(img, x0, y1), pixel(img, x1, y1), pixel(img, x0, y0), pixel(img, x1, y0)};
}

// Texels (r, g, b): (0, 0) = (200, 10, 20), (1, 0) = (30, 220, 40), (0, 1) = (50, 60, 230),
// (1, 1) = (250, 250, 5); row 0 is memory row 0, GX's t = 0, the map's v = 0: the bottom.
const std::array<std::array<int, 3>, 4> kTexels = {
    {{200, 10, 20}, {30, 220, 40}, {50, 60, 230}, {250, 250, 5}}};

TEST(GxMapProgram, Rgba8MapInTexmap1ShowsItsTexelsTheRightWayUp) {
  // RGBA8 2 x 2 (one 64-byte tile): texel (x, y) is tile texel y*4 + x; (a, r) at twice that,
  // (g, b) 32 bytes further.
  std::vector<gx::u8> tiles(64, 0);
  const int slot[4] = {0, 1, 4, 5};
  for (int i = 0; i < 4; ++i) {
    tiles[static_cast<size_t>(slot[i] * 2)] = 255;
    tiles[static_cast<size_t>(slot[i] * 2 + 1)] = static_cast<gx::u8>(kTexels[i][0]);
    tiles[static_cast<size_t>(32 + slot[i] * 2)] = static_cast<gx::u8>(kTexels[i][1]);
    tiles[static_cast<size_t>(32 + slot[i] * 2 + 1)] = static_cast<gx::u8>(kTexels[i][2]);
  }
  test::TempDir dir;
  test::write_file(dir / "map.c", map_program(tiles, "GX_TF_RGBA8"));
  const Image img =
      render_scene(uv_quad_scene(dir, true), "gx", "", 0, 0, {(dir / "map.c").string()});
  EXPECT_EQ(corners(img), kTexels);
}

TEST(GxMapProgram, Rgb565AndI8MapsDecodeAsTheHardwareExpands) {
  // RGB565 2 x 2 (one 32-byte tile), big-endian: (0, 0) = 0xF800 red, (1, 0) = 0x07E0 green,
  // (0, 1) = 0x001F blue, (1, 1) = 0x8410 (16, 32, 16) -> (132, 130, 132).
  std::vector<gx::u8> rgb565(32, 0);
  rgb565[0] = 0xF8;
  rgb565[2] = 0x07, rgb565[3] = 0xE0;
  rgb565[9] = 0x1F;  // tile texel 4 (x 0, y 1) at byte 8
  rgb565[10] = 0x84, rgb565[11] = 0x10;
  test::TempDir dir;
  const Scene scene = uv_quad_scene(dir, true);
  test::write_file(dir / "rgb565.c", map_program(rgb565, "GX_TF_RGB565"));
  const std::array<std::array<int, 3>, 4> expanded = {
      {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {132, 130, 132}}};
  EXPECT_EQ(corners(render_scene(scene, "gx", "", 0, 0, {(dir / "rgb565.c").string()})), expanded);
  // I8 2 x 2 (one 8x4 tile of 32 bytes): (x, y) at y*8 + x.
  std::vector<gx::u8> i8(32, 0);
  i8[0] = 17, i8[1] = 99, i8[8] = 180, i8[9] = 254;
  test::write_file(dir / "i8.c", map_program(i8, "GX_TF_I8"));
  const std::array<std::array<int, 3>, 4> grey = {
      {{17, 17, 17}, {99, 99, 99}, {180, 180, 180}, {254, 254, 254}}};
  EXPECT_EQ(corners(render_scene(scene, "gx", "", 0, 0, {(dir / "i8.c").string()})), grey);
}

// What the stream cannot feed is refused with the file and the pass, exit 2, nothing written.
void expect_program_refused(const std::string& program, bool uvs, const std::string& message) {
  test::TempDir dir;
  const Scene scene = uv_quad_scene(dir, uvs);
  test::write_file(dir / "p.c", program);
  try {
    render_scene(scene, "gx", "", 0, 0, {(dir / "p.c").string()});
    ADD_FAILURE() << "accepted: " << message;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("p.c"), std::string::npos) << e.what();
  }
}

TEST(GxMapProgram, UvsOfAMeshWithoutThemAreRefused) {
  const std::string p = map_program(std::vector<gx::u8>(64, 0), "GX_TF_RGBA8");
  expect_program_refused(
      p, false,
      "texgen GX_TEXCOORD0 reads the mesh's UVs (GX_VA_TEX0 as GX_TEX_ST), but a mesh "
      "of this material has none");
}

TEST(GxMapProgram, ATexCoordAboveAGapIsRefused) {
  std::string p = map_program(std::vector<gx::u8>(64, 0), "GX_TF_RGBA8");
  // Move the UV to GX_VA_TEX1 with no GX_VA_TEX0: the XF counts texture coordinates.
  for (const std::string from : {"GX_VA_TEX0", "GX_TG_TEX0"}) {
    std::string to = from;
    to.back() = '1';
    for (size_t at; (at = p.find(from)) != std::string::npos;) p.replace(at, from.size(), to);
  }
  expect_program_refused(p, true, "the vertex format has GX_VA_TEX1 but no GX_VA_TEX0");
}

TEST(GxMapProgram, AnUnloadedTexmap1AndAnUnmodelledFormatAreRefused) {
  std::string p = map_program(std::vector<gx::u8>(64, 0), "GX_TF_RGBA8");
  std::string unloaded = p;
  unloaded.replace(unloaded.find("GX_LoadTexObj(&tex, GX_TEXMAP1);"), 32, "");
  expect_program_refused(unloaded, true, "TEV stage 0 fetches GX_TEXMAP1, which holds no texture");
  std::string indexed = p;
  indexed.replace(indexed.find("GX_TF_RGBA8"), 11, "GX_TF_CI8");
  expect_program_refused(indexed, true, "a colour-indexed format needs GX_InitTexObjCI");
}

// A CI4 2 x 2 map (one 8x8 tile of 32 bytes, two texels a byte, the first in the high nibble:
// (x, y) at byte y*4 + x/2) whose IA8 palette (alpha first, intensity second) is loaded into
// GX_TLUT0 by GX_InitTlutObj + GX_LoadTlut and named by GX_InitTexObjCI.
std::string ci4_program(int entries, const std::string& load_tlut) {
  std::vector<gx::u8> tiles(32, 0);
  tiles[0] = 0x12;  // (0, 0) index 1, (1, 0) index 2
  tiles[4] = 0x30;  // (0, 1) index 3, (1, 1) index 0
  const std::vector<gx::u8> palette{255, 250, 255, 200, 255, 30, 255, 50};
  std::string p = map_program(tiles, "GX_TF_CI4");
  const std::string init =
      "GX_InitTexObj(&tex, map, 2, 2, GX_TF_CI4, GX_CLAMP, GX_CLAMP, GX_FALSE);";
  p.replace(p.find(init), init.size(),
            "GX_InitTlutObj(&pal, palette, GX_TL_IA8, " + std::to_string(entries) + ");\n" +
                load_tlut +
                "GX_InitTexObjCI(&tex, map, 2, 2, GX_TF_CI4, GX_CLAMP, GX_CLAMP, GX_FALSE, "
                "GX_TLUT0);");
  return test::c_byte_array("palette", palette) + "GXTlutObj pal;\n" + p;
}

TEST(GxMapProgram, Ci4MapReadsItsIa8PaletteThroughTheTlut) {
  test::TempDir dir;
  test::write_file(dir / "ci4.c", ci4_program(4, "GX_LoadTlut(&pal, GX_TLUT0);\n"));
  // Each corner is its index's entry, IA8's intensity in r, g and b [DHW
  // TextureDecoder_Common.cpp DecodePixel_Paletted, DecodePixel_IA8].
  const std::array<std::array<int, 3>, 4> want = {
      {{200, 200, 200}, {30, 30, 30}, {50, 50, 50}, {250, 250, 250}}};
  EXPECT_EQ(
      corners(render_scene(uv_quad_scene(dir, true), "gx", "", 0, 0, {(dir / "ci4.c").string()})),
      want);
}

TEST(GxMapProgram, ACi4MapWithoutItsTlutOrWithTooFewEntriesIsRefused) {
  expect_program_refused(ci4_program(4, ""), true, "TLUT 0 was never loaded (GX_LoadTlut)");
  // Index 3 is past a TLUT of three entries.
  expect_program_refused(ci4_program(3, "GX_LoadTlut(&pal, GX_TLUT0);\n"), true,
                         "map holds palette index 3, TLUT 0 has 3 entries");
  // GX_TLUT0 holds 256 entries [OGC gx.c GX_Init's GX_InitTlutRegion(.., GX_TLUT_256)].
  std::string big = ci4_program(4, "GX_LoadTlut(&pal, GX_TLUT0);\n");
  big.replace(big.find("GX_TL_IA8, 4"), 12, "GX_TL_IA8, 257");
  big.replace(big.find("palette[8]"), 10, "palette[514]");
  expect_program_refused(big, true, "GX_TLUT0 holds 256 entries, the TLUT has 257");
}

}  // namespace
}  // namespace lt
