// Every map format `:map=FMT` offers (gx_variant.h) judged by Dolphin: the map scenes' colour
// map (scenes/maps/sphere_rgb_ramp.json) as RGB565, RGB5A3, CMPR and CI8 (RGB565 TLUT), their
// grey map (scenes/maps/sphere_map.json) as IA8, IA4, I4 and CI4 (IA8 TLUT), and the I4 map with
// the power LUT as I4 (:lut-format=i4), the nine frames in
// one FIFO log (one Dolphin start: dolphin_util.h dolphin_pictures with a scene a frame), each
// frame's texture in its format in the log's memory and TexImage0, a colour-indexed one's
// palette in memory and loaded into TMEM by BP_LOADTLUT0/1, its TMEM offset and format in the
// map's TLUT register (frame_recording.cpp, bp_registers.cpp). Dolphin's software renderer
// decodes them ([DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel], the palette at
// texMem[offset << 9] [DSW TextureSampler.cpp SampleMip]), and its picture must be ltrender's
// `:out=xfb` one, pixel for pixel. The defaults (RGBA8, I8) are
// judged by dolphin_judge_test.cpp's demo scenes.
//
// Then the same formats, the defaults too, from seeded images (issue 47 item 6): a 16 x 16 RGBA
// PNG of random bytes from a fixed seed, written into the test's directory, is the colour map
// (its RGB) of RGBA8, RGB565, RGB5A3, CMPR, CI8 and CI4 frames and the grey map (its alpha, the
// scene's `"channels": "a"`) of I8, IA8, IA4, I4, CI8 and CI4 frames: every texel differs from
// its neighbours, so a texel decoded from the wrong bytes, tile or palette entry shows. The map
// path stores no alpha of its own (alpha 255: thickness_texture.h), so the formats' alpha bits
// are the same in every frame.
//
// Then CI14X2, which is not a map format (gx_variant.h says why): two frames of a porter's own
// GX C (ci14_program, given as the frame's program file as `render --program` and `export
// --format dff --program` take it), a 16 x 16 CI14X2 texture of random indices with random top
// bits, its palette 1,024 RGB565 entries in GX_BIGTLUT0 or 256 RGB5A3 ones in GX_TLUT3.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <utility>

#include "dolphin_util.h"
#include "gx_program_util.h"
#include "image/png_file.h"
#include "load/load_scene.h"
#include "load/thickness_map.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

// A porter's own GX C drawing a CI14X2 (GX_TF_CI14) texture: not a map format (gx_variant.h),
// so only a program file reaches it. The palette's TLUT format, the TLUT region it is loaded
// into and its entries (at most the region's: 1,024 for GX_BIGTLUT*, 256 for GX_TLUT*).
struct Ci14Program {
  const char* tlut_format;  // GX_TL_RGB565, GX_TL_RGB5A3, GX_TL_IA8
  const char* tlut_name;    // GX_BIGTLUT0, GX_TLUT3, ...
  int entries;
};

struct MapFrame {
  const char* scene;
  const char* variant;
  const char* seeded_channels = nullptr;  // the seeded PNG's channels as the map ("rgb", "a")
  const Ci14Program* program = nullptr;   // drawn by this program file instead
};

// A side x side RGBA PNG of bytes from std::mt19937(seed), every channel and alpha random.
void write_seeded_png(const std::filesystem::path& file, int side, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> rgba(static_cast<size_t>(side) * side * 4);
  for (std::uint8_t& b : rgba) b = static_cast<std::uint8_t>(rng() >> 24);
  std::string error;
  ASSERT_TRUE(write_png_rgba8(file.string(), side, side, rgba.data(), error)) << error;
}

// The program a porter writes for a 16 x 16 CI14X2 texture in GX_TEXMAP1, shown by one TEV
// stage (GX_REPLACE) at the mesh's UV, every face drawn. Its palette is `c.entries` random
// entries (std::mt19937(seed)), loaded by GX_InitTlutObj + GX_LoadTlut into `c.tlut_name` and
// named by GX_InitTexObjCI. Each texel is a random index over the whole palette, stored as a
// big-endian u16 (4x4 tiles of 32 bytes: texture_decoder.h) whose top two bits are random too:
// Dolphin reads the low 14 bits [DHW TextureDecoder_Common.cpp TexDecoder_DecodeTexel, case
// C14X2 `swap16(...) & 0x3FFF`], so a decoder that kept them, or read the bytes little-endian,
// would fetch entries far past the palette (TMEM beyond the region, in Dolphin).
std::string ci14_program(const Ci14Program& c, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> palette(static_cast<size_t>(c.entries) * 2), map(16 * 16 * 2);
  for (std::uint8_t& b : palette) b = static_cast<std::uint8_t>(rng() >> 24);
  for (size_t t = 0; t < map.size(); t += 2) {
    const unsigned index = static_cast<unsigned>(rng() % static_cast<unsigned>(c.entries));
    const unsigned top = (rng() >> 30) << 14;  // bits 14 and 15, ignored by the hardware
    map[t] = static_cast<std::uint8_t>((top | index) >> 8);
    map[t + 1] = static_cast<std::uint8_t>(index & 0xff);
  }
  const std::string tlut = c.tlut_name;
  return test::c_byte_array("palette", palette) + test::c_byte_array("map", map) +
         "GXTlutObj pal;\nGXTexObj tex;\n" +
         "GX_SetCullMode(GX_CULL_NONE);\n"
         "GX_ClearVtxDesc();\n"
         "GX_SetVtxDesc(GX_VA_POS, GX_DIRECT);\n"
         "GX_SetVtxDesc(GX_VA_TEX0, GX_DIRECT);\n"
         "GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_POS, GX_POS_XYZ, GX_F32, 0);\n"
         "GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_TEX0, GX_TEX_ST, GX_F32, 0);\n"
         "GX_SetNumChans(0);\n"
         "GX_SetNumTexGens(1);\n"
         "GX_SetTexCoordGen(GX_TEXCOORD0, GX_TG_MTX2x4, GX_TG_TEX0, GX_IDENTITY);\n"
         "GX_InitTlutObj(&pal, palette, " +
         c.tlut_format + ", " + std::to_string(c.entries) + ");\n" + "GX_LoadTlut(&pal, " + tlut +
         ");\n" + "GX_InitTexObjCI(&tex, map, 16, 16, GX_TF_CI14, GX_CLAMP, GX_CLAMP, GX_FALSE, " +
         tlut +
         ");\n"
         "GX_LoadTexObj(&tex, GX_TEXMAP1);\n"
         "GX_SetNumTevStages(1);\n"
         "GX_SetTevOrder(GX_TEVSTAGE0, GX_TEXCOORD0, GX_TEXMAP1, GX_COLORNULL);\n"
         "GX_SetTevOp(GX_TEVSTAGE0, GX_REPLACE);\n";
}

TEST(DolphinMapFormat, EveryMapFormatIsDolphinsPicture) {
  // CI14X2 from a porter's program: 1,024 RGB565 entries in a big TLUT, 256 RGB5A3 ones (the
  // TLUT format no map frame uses) in a small one.
  const Ci14Program ci14_rgb565{"GX_TL_RGB565", "GX_BIGTLUT0", 1024},
      ci14_rgb5a3{"GX_TL_RGB5A3", "GX_TLUT3", 256};
  const MapFrame cases[] = {{"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=rgb565"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=rgb5a3"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=cmpr"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ia8"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ia4"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=i4"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=ci8"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ci4"},
                            // The power LUT as I4 (:lut-format=, docs/textures.md).
                            {"scenes/maps/sphere_map.json", "t=vertex:map=i4:lut-format=i4"},
                            // The seeded image: colour formats from its RGB...
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex", "rgb"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=rgb565", "rgb"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=rgb5a3", "rgb"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=cmpr", "rgb"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=ci8", "rgb"},
                            {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=ci4", "rgb"},
                            // ... grey ones from its alpha.
                            {"scenes/maps/sphere_map.json", "t=vertex", "a"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ia8", "a"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ia4", "a"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=i4", "a"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ci8", "a"},
                            {"scenes/maps/sphere_map.json", "t=vertex:map=ci4", "a"},
                            // CI14X2 in users' GX C (--program).
                            {"scenes/maps/sphere_map.json", "t=vertex", nullptr, &ci14_rgb565},
                            {"scenes/maps/sphere_map.json", "t=vertex", nullptr, &ci14_rgb5a3}};
  constexpr size_t kFrames = std::size(cases);
  test::TempDir dir;
  const std::filesystem::path seeded = dir / "seeded_rgba.png";
  write_seeded_png(seeded, 16, 47);
  std::vector<Scene> scenes;
  std::vector<std::string> programs;
  for (const MapFrame& c : cases) {
    programs.emplace_back();
    if (c.program) {
      programs.back() = (dir / ("ci14_" + std::to_string(scenes.size()) + ".c")).string();
      test::write_file(programs.back(), ci14_program(*c.program, 47 + scenes.size()));
    }
    scenes.push_back(load_scene(test::source_dir() / c.scene));
    scenes.back().width = test::kDolphinWidth;
    scenes.back().height = test::kDolphinHeight;
    // The seeded frames draw the sphere smaller (a quarter of its pixels): the random texels
    // still cover it with every texel magnified, at less of the suite's time.
    if (c.seeded_channels || c.program) scenes.back().camera.fov_y_deg = 80;
    if (c.seeded_channels)
      scenes.back().materials.at(0).translucency->thickness_map =
          load_thickness_map(seeded, c.seeded_channels, scenes.back().file.string(), "thickness");
  }
  std::vector<std::string> variants;
  for (const MapFrame& c : cases) variants.push_back(c.variant);
  const std::vector<Image> dolphin = test::dolphin_pictures_of(scenes, variants, programs);
  ASSERT_EQ(dolphin.size(), kFrames);
  // The formats change the picture, so matching each frame means Dolphin decoded that frame's
  // format, not one format six times: RGB565, RGB5A3 and CMPR differ from each other, IA8 from
  // IA4. IA4 and I4 hold the same 4-bit intensity (the alpha is unused), so they draw one
  // picture from different tiles (8x4 of bytes, 8x8 of nibbles: a wrong format reads others).
  // The colour-indexed frames differ from the direct formats of their map (CI8's 256 RGB565
  // entries from RGB565's texels, CI4's 16 IA8 entries from IA8's texels); the I4 LUT's frame
  // from the I8 LUT's.
  // The seeded frames: each colour format from RGBA8's, each grey one from I8's but IA8's and
  // CI8's, which keep the 8-bit greys exactly (IA8's intensity byte; CI8's 256 IA8 entries for
  // 256 texels) and so draw I8's picture from other bytes (IA8's 4x4 tiles of 16 bits); IA4 and
  // I4 again draw one picture. The two CI14X2 frames differ (other indices, other palettes).
  const std::pair<size_t, size_t> differing[] = {
      {0, 1},  {0, 2},  {1, 2},  {3, 4},  {3, 5},   {6, 0},   {7, 3},   {8, 5},  {10, 9},
      {11, 9}, {12, 9}, {13, 9}, {14, 9}, {17, 15}, {18, 15}, {20, 15}, {21, 22}};
  for (const auto& [k, j] : differing)
    EXPECT_GT(test::picture_difference(dolphin[k], dolphin[j]).differ, 0u)
        << cases[k].variant << " and " << cases[j].variant << " draw the same picture";
  for (size_t k = 0; k < kFrames; ++k) {
    PathOptions options;
    options.program_file = programs[k];
    const Image ours = render_scene(scenes[k], "gx", std::string(cases[k].variant) + ":out=xfb",
                                    test::kDolphinWidth, test::kDolphinHeight, options);
    const test::PictureDifference d = test::picture_difference(ours, dolphin[k]);
    const std::string name =
        std::string(cases[k].variant) +
        (cases[k].program ? std::string(" --program (CI14X2, ") + cases[k].program->tlut_format +
                                " in " + cases[k].program->tlut_name + ")"
                          : "");
    std::printf("| %s | %s | %zu | %zu | %d |\n", cases[k].scene, name.c_str(),
                test::covered_pixels(ours), d.differ, d.max);
    EXPECT_GT(test::covered_pixels(ours), static_cast<size_t>(ours.pixel_count() / 50))
        << cases[k].variant << ": the scene covers almost nothing";
    EXPECT_EQ(d.differ, 0u) << cases[k].scene << " " << cases[k].variant << ": first at "
                            << d.first_x << "," << d.first_y << ", max " << d.max << " LSB";
  }
}

}  // namespace
}  // namespace lt
