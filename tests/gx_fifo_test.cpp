// The gx path's frame as a Dolphin FIFO log (src/gx/fifo/, recorded by
// src/paths/gx/frame_recording.h): register words against libogc's own arithmetic worked by hand,
// every pass of every demo scene and gx variant decoded back to the state the emulator runs, the
// whole frame walked as a command processor would, the container read back, and `export gx --format
// dff`'s refusals.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "gx/fifo/bp_registers.h"
#include "gx/fifo/cp_registers.h"
#include "gx/fifo/fifo_log.h"
#include "gx/fifo/state_decoder.h"
#include "gx/fifo/stream_reader.h"
#include "gx/fifo/xf_registers.h"
#include "load/load_scene.h"
#include "paths/gx/camera_transform.h"
#include "paths/gx/frame_recording.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/lobe_lut.h"
#include "paths/gx/scene_vertices.h"
#include "test_util.h"

namespace lt::gx::fifo {
namespace {

// ---- Register words worked by hand from libogc's gx.c (the line numbers are gx.c's).

// GX_SetTevColorIn(GX_TEVSTAGE0, GX_CC_ZERO 15, GX_CC_RASC 10, GX_CC_KONST 14, GX_CC_ZERO 15)
// (L3871: a << 12, b << 8, c << 4, d) and GX_SetTevColorOp(.., GX_TEV_ADD, GX_TB_ZERO,
// GX_CS_SCALE_1, GX_TRUE, GX_TEVPREV) (L3893: clamp << 19): 0xF000 | 0xA00 | 0xE0 | 0xF | 0x80000.
TEST(GxFifoBits, TevColorCombinerIsLibogcsWord) {
  TevStage s;
  s.color = TevCombiner{15, 10, 14, 15, 0, 0, 0, true, 0};
  EXPECT_EQ(tev_color_env(s), 0x8FAEFu);
  // A compare stage, GX_TEV_COMP_RGB8_EQ (15) to GX_TEVREG1: bias 3 << 16, op 15 & 1 << 18,
  // ((15 << 19) & 0x300000) = 3 << 20, clamp 0, dest 2 << 22 (L3899-3903).
  s.color = TevCombiner{0, 0, 0, 0, 3, 1, 3, false, 2};
  EXPECT_EQ(tev_color_env(s), 0x30000u | 0x40000u | 0x300000u | 0x800000u);
}

// GX_SetTevAlphaIn(stage, GX_CA_TEXA 4, GX_CA_RASA 5, GX_CA_KONST 6, GX_CA_ZERO 7) (L3882: a << 13,
// b << 10, c << 7, d << 4), GX_SetTevSwapMode(stage, GX_TEV_SWAP1, GX_TEV_SWAP2) (L4068: ras 0-1,
// tex 2-3), GX_SetTevAlphaOp(.., GX_TEV_SUB 1, GX_TB_ADDHALF 1, GX_CS_SCALE_2 1, GX_FALSE,
// GX_TEVREG0 1): 0x8000 | 0x1400 | 0x300 | 0x70 | 1 | 8 | 0x40000 | 0x10000 | 0x100000 | 0x400000.
TEST(GxFifoBits, TevAlphaCombinerCarriesTheSwaps) {
  TevStage s;
  s.alpha = TevCombiner{4, 5, 6, 7, 1, 1, 1, false, 1};
  s.ras_swap = 1;
  s.tex_swap = 2;
  EXPECT_EQ(tev_alpha_env(s),
            0x8000u + 0x1400 + 0x300 + 0x70 + 1 + 8 + 0x40000 + 0x10000 + 0x100000 + 0x400000);
}

// GX_SetTevOrder(GX_TEVSTAGE0, GX_TEXCOORDNULL, GX_TEXMAP_NULL, GX_COLOR0A0) writes 0 in the low
// half; GX_SetTevOrder(GX_TEVSTAGE1, GX_TEXCOORD2, GX_TEXMAP1, GX_COLOR1A1) texmap 1 << 12,
// texcoord 2 << 15, enable 1 << 18, _gxtevcolid[5] = 1 << 19 (L3988-4031).
TEST(GxFifoBits, TevOrderIsLibogcsWord) {
  TevState tev;
  tev.stages[0] = TevStage{kTexCoordNull, kTexMapNull, 4, {}, {}, 6, 0, 0, 0};
  tev.stages[1] = TevStage{2, 1, 5, {}, {}, 6, 0, 0, 0};
  EXPECT_EQ(tev_order(tev, 0), 0x1000u + 0x10000 + 0x40000 + 0x80000);
  // GX_COLORNULL and GX_COLORZERO both write 7 (GX_ALPHA_BUMP / _gxtevcolid[6]).
  tev.stages[0].channel = kColorNull;
  EXPECT_EQ(tev_order(tev, 0) & 0xfff, 7u << 7);
}

// GX_Init's genmode: 1 texgen, 0 channels, 1 stage (0 << 10), GX_CULL_BACK -> cm2hw[2] = 1 << 14
// (L3929-3935): 0x4001. One channel, three stages, GX_CULL_NONE: 0x10 | 2 << 10 = 0x811.
TEST(GxFifoBits, GenModeSwapsTheCullModeAsLibogcDoes) {
  GxState s;
  EXPECT_EQ(gen_mode(s), 0x4001u);
  s.lighting.num_channels = 1;
  s.tev.num_stages = 3;
  s.cull_mode = kCullNone;
  EXPECT_EQ(gen_mode(s), 0x811u);
  s.cull_mode = kCullFront;  // cm2hw[1] = 2
  EXPECT_EQ(gen_mode(s) >> 14, 2u);
}

// GX_SetTevKColor(GX_KCOLOR1, {10, 20, 30, 40}) (L3805): RA 1 << 23 | 40 << 12 | 10, BG 1 << 23 |
// 20 << 12 | 30; GX_SetTevColorS10(GX_TEVREG0, {-1, 2, -1024, 1023}) (L3790): RA 1023 << 12 |
// 0x7ff, BG 2 << 12 | 0x400.
TEST(GxFifoBits, KonstAndRegisterWordsAreLibogcs) {
  EXPECT_EQ(tev_konst(Color8{10, 20, 30, 40}), (std::array<u32, 2>{0x82800Au, 0x81401Eu}));
  EXPECT_EQ(tev_register(ColorS10{-1, 2, -1024, 1023}), (std::array<u32, 2>{0x3FF7FFu, 0x2400u}));
}

// GX_SetAlphaCompare(GX_GREATER 4, 10, GX_AOP_OR 1, GX_LESS 1, 200) (L4039): 1 << 22 | 1 << 19 |
// 4 << 16 | 200 << 8 | 10. GX_SetZMode(GX_TRUE, GX_LEQUAL 3, GX_FALSE) (L2948): 1 | 3 << 1.
// GX_SetBlendMode(GX_BM_BLEND, GX_BL_ONE, GX_BL_ONE, GX_LO_CLEAR) with GX_Init's dither and
// updates (L3735, L4377-4415): 1 | 4 | 8 | 0x10 | 1 << 5 | 1 << 8, and without the dither
// (GX_SetDither(GX_FALSE), bit 2): 0x139; GX_Init's own blend (GX_BM_NONE, SRCALPHA 4,
// INVSRCALPHA 5): 0x1C | 5 << 5 | 4 << 8. GX_SetPixelFmt(GX_PF_RGBA6_Z24, GX_ZC_MID) with
// GX_SetZCompLoc(GX_TRUE): 1 | 2 << 3 | 1 << 6.
TEST(GxFifoBits, PixelEngineWordsAreLibogcs) {
  EXPECT_EQ(alpha_compare(AlphaCompare{4, 10, 1, 1, 200}), 0x4CC80Au);
  EXPECT_EQ(z_mode(ZMode{true, 3, false}), 7u);
  EXPECT_EQ(blend_mode(BlendMode{1, 1, 1, 0}, true), 0x13Du);
  EXPECT_EQ(blend_mode(BlendMode{1, 1, 1, 0}, false), 0x139u);
  EXPECT_EQ(blend_mode(BlendMode{}, true), 0x4BCu);
  EXPECT_EQ(pixel_control(PixelFormat{kPixelRgba6Z24, 2}), 0x51u);
  EXPECT_EQ(pixel_control(PixelFormat{}), 0x40u);
}

// GX_Init's konst selections and swap table 0 (L686-694): BP 0xF6 = r 0 | g 1 << 2 | KCSEL_1_4
// (6) << 4 | KASEL_1 (0) << 9 | 6 << 14 | 0 << 19.
TEST(GxFifoBits, KonstSelectSharesTheSwapTable) {
  const TevState tev;
  EXPECT_EQ(tev_konst_select(tev, 0), 0x4u | 0x60u | 0x18000u);
  EXPECT_EQ(tev_konst_select(tev, 1), 2u | 3u << 2 | 0x60u | 0x18000u);  // table 0's b, a
}

// GX_SetChanCtrl(GX_COLOR0A0, GX_ENABLE, GX_SRC_REG, GX_SRC_VTX, GX_LIGHT0 | GX_LIGHT5,
// GX_DF_CLAMP, GX_AF_SPOT) (L2193): 1 | 1 << 1 | (0x21 & 0xf) << 2 | 2 << 7 | (2 - 1 > 0) << 9 |
// (1 > 0) << 10 | (0x21 >> 4) << 11 = 0x1707; with GX_AF_SPEC the diffuse function is forced to
// GX_DF_NONE and both attenuation bits read 1, 0.
TEST(GxFifoBits, ChannelControlIsLibogcsWord) {
  EXPECT_EQ(channel_control(ChannelControl{true, 0, 1, 0x21, 2, 1}), 0x1707u);
  EXPECT_EQ(channel_control(ChannelControl{true, 0, 1, 0x01, 2, 0}), 0x207u);
}

// GX_SetTexCoordGen(n, GX_TG_MTX2x4, GX_TG_NRM, ..) (L2658-2744): stq 1 << 2 | row 1 << 7 =
// 0x84; (GX_TG_MTX3x4, GX_TG_TEX1): 0x2 | row 6 << 7 = 0x302.
TEST(GxFifoBits, TexGenRowIsLibogcsWord) {
  EXPECT_EQ(texgen_word(TexGen{1, 1, 30}), 0x84u);
  EXPECT_EQ(texgen_word(TexGen{0, 5, 60}), 0x302u);
}

// GX_InitTexObj(obj, 0x01040000, 256, 1, GX_TF_I8, GX_CLAMP, GX_CLAMP, GX_FALSE) loaded into
// GX_TEXMAP0 (L3226-3298, L3443-3470): mode0 0x10 | 4 << 5; image0 255 | 0 << 10 | 1 << 20;
// image3 0x01040000 >> 5; the region texRegion[8]: even 0x00000, odd 0x80000, 32 KiB (3) in
// both size fields (L3149-3191).
TEST(GxFifoBits, TextureRegistersAreLibogcs) {
  TextureObject t;
  t.width = 256;
  t.height = 1;
  t.format = kTexFormatI8;
  const TextureRegisters r = texture_registers(t, 0, 0x01040000);
  EXPECT_EQ(r.mode0, 0x90u);
  EXPECT_EQ(r.mode1, 0u);
  EXPECT_EQ(r.image0, 0x1000FFu);
  EXPECT_EQ(r.image1, 0xD8000u);
  EXPECT_EQ(r.image2, 0x4000u | 0xD8000u);
  EXPECT_EQ(r.image3, 0x82000u);
}

// GX_InitTlutObj(&tlut, 0x01041000, GX_TL_RGB565, 20), GX_LoadTlut(&tlut, GX_TLUT1) and
// GX_InitTexObjCI(.., 8, 4, GX_TF_CI8, .., GX_TLUT1) loaded into GX_TEXMAP2 (L3421-3431,
// L3648-3663, L3443-3474): BP 0x64 = 0x01041000 >> 5; GX_TLUT1's region at 0xC2000 gives
// offset (0xC2000 - 0x80000) >> 9 = 0x210 and BP 0x65 = 0x210 | GX_TLUT_256 (16 lines) << 10,
// the whole region whatever the entries; the TLUT register 0x9A = 0x210 | GX_TL_RGB565 << 10;
// the texture's region texRegion[2]: even 0x20000, odd 0x28000. Read back: the decoder's state
// holds the TLUT's format and offset.
TEST(GxFifoBits, AColourIndexedTextureLoadsItsTlutAsLibogc) {
  TextureObject t;
  t.width = 8;
  t.height = 4;
  t.format = 9;  // GX_TF_CI8
  t.data.assign(32, 0);
  t.tlut.assign(40, 0);
  t.tlut_format = 1;
  t.tlut_offset = 0x210;
  const TextureRegisters r = texture_registers(t, 2, 0x01040000);
  EXPECT_EQ(r.tlut, 0x210u | (1u << 10));
  EXPECT_EQ(r.image1, (0x20000u >> 5) | 0xD8000u);
  EXPECT_EQ(r.image2, (0x28000u >> 5) | 0xD8000u);
  CommandStream out;
  GxState s;
  s.textures[2] = t;
  std::array<const TextureObject*, kMaxTexMaps> textures{};
  textures[2] = &t;
  std::array<u32, kMaxTexMaps> addresses{}, tlut_addresses{};
  addresses[2] = 0x01040000;
  tlut_addresses[2] = 0x01041000;
  write_pass_bp(out, s, textures, addresses, tlut_addresses);
  RegisterFile regs;
  read_stream(out.bytes(), regs, "ci8");
  EXPECT_EQ(regs.bp[0x64], 0x01041000u >> 5);
  EXPECT_EQ(regs.bp[0x65], 0x210u | (16u << 10));
  EXPECT_EQ(regs.bp[0x9A], 0x210u | (1u << 10));
  const DecodedPass d = decode_pass(regs);
  ASSERT_TRUE(d.state.textures[2]);
  EXPECT_EQ(d.state.textures[2]->format, 9);
  EXPECT_EQ(d.state.textures[2]->tlut_format, 1);
  EXPECT_EQ(d.state.textures[2]->tlut_offset, 0x210);
}

// GX_SetVtxDesc of POS, NRM, CLR0 and TEX0 as GX_DIRECT (L2295-2367): VCD low 1 << 9 | 1 << 11 |
// 1 << 13, high 1; GX_SetVtxAttrFmt(GX_VTXFMT0, GX_VA_TEX0, GX_TEX_S, GX_F32, 0) leaves bit 21
// clear, GX_TEX_ST sets it; __GX_XfVtxSpecs: 1 colour | 1 normal << 2 | 1 texcoord << 4.
TEST(GxFifoBits, VertexDescriptorIsLibogcs) {
  VertexDescriptor v;
  for (int a : {kVaPos, kVaNrm, kVaClr0, kVaTex0}) v.type[static_cast<size_t>(a)] = 1;
  EXPECT_EQ(vcd_low(v), 0x2A00u);
  EXPECT_EQ(vcd_high(v), 1u);
  EXPECT_EQ(vertex_specs(v), 0x15u);
  TexCoordFormats f;
  f.kind[0] = TexCoordFormats::S;
  EXPECT_EQ(vertex_attribute_formats(f)[0] >> 21 & 1, 0u);
  f.kind[0] = TexCoordFormats::ST;
  EXPECT_EQ(vertex_attribute_formats(f)[0] >> 21 & 1, 1u);
  EXPECT_EQ(vertex_attribute_formats(f)[0] >> 22 & 7, 4u);  // GX_F32
}

// GX_SetViewport(0, 0, 320, 240, 0, 1) (L1767-1795): 160, -120, 2^24 - 1, 160 + 342, 120 + 342,
// 2^24 - 1.
TEST(GxFifoBits, ViewportHasLibogcsOffset) {
  const auto w = viewport_words({320, 240});
  const float expected[6] = {160, -120, 16777215, 502, 462, 16777215};
  for (int i = 0; i < 6; ++i) EXPECT_EQ(bits_float(w[static_cast<size_t>(i)]), expected[i]) << i;
}

// A perspective camera at the near plane maps to GX clip z = -w, at the far plane to 0 (libogc's
// guPerspective convention); an orthographic one to -1 and 0 with w = 1.
TEST(GxFifoBits, ProjectionClipsZToMinusWToZero) {
  Camera cam;
  cam.near = 0.5;
  cam.far = 10;
  const auto p = projection_words(view_transform(glm::mat3(1.0f), cam, {320, 240}));
  auto z_over_w = [&](double z) { return (bits_float(p[4]) * z + bits_float(p[5])) / -z; };
  EXPECT_EQ(p[6], 0u);
  EXPECT_NEAR(z_over_w(-0.5), -1.0, 1e-6);
  EXPECT_NEAR(z_over_w(-10), 0.0, 1e-6);
  cam.projection = Camera::Projection::Orthographic;
  const auto o = projection_words(view_transform(glm::mat3(1.0f), cam, {320, 240}));
  EXPECT_EQ(o[6], 1u);
  EXPECT_NEAR(bits_float(o[4]) * -0.5 + bits_float(o[5]), -1.0, 1e-6);
  EXPECT_NEAR(bits_float(o[4]) * -10 + bits_float(o[5]), 0.0, 1e-6);
}

// ---- Round trips on every demo scene and gx variant.

void expect_same_state(const GxState& got, const GxState& want, const std::string& where) {
  EXPECT_EQ(got.cull_mode, want.cull_mode) << where;
  EXPECT_TRUE(got.z == want.z) << where << ": z mode";
  EXPECT_TRUE(got.blend == want.blend) << where << ": blend";
  EXPECT_TRUE(got.alpha_compare == want.alpha_compare) << where << ": alpha compare";
  EXPECT_TRUE(got.vertex == want.vertex) << where << ": vertex descriptor";
  EXPECT_TRUE(got.texcoord_formats == want.texcoord_formats) << where << ": texcoord formats";
  EXPECT_EQ(got.tev.num_stages, want.tev.num_stages) << where;
  for (size_t s = 0; s < kMaxTevStages; ++s)
    EXPECT_TRUE(got.tev.stages[s] == want.tev.stages[s]) << where << ": TEV stage " << s;
  EXPECT_TRUE(got.tev.registers == want.tev.registers) << where << ": TEV registers";
  EXPECT_TRUE(got.tev.konst == want.tev.konst) << where << ": konst colours";
  EXPECT_TRUE(got.tev.swap_tables == want.tev.swap_tables) << where << ": swap tables";
  EXPECT_EQ(got.lighting.num_channels, want.lighting.num_channels) << where;
  for (size_t c = 0; c < 4; ++c)
    EXPECT_TRUE(got.lighting.control[c] == want.lighting.control[c]) << where << ": control " << c;
  EXPECT_TRUE(got.lighting.ambient == want.lighting.ambient) << where << ": ambient";
  EXPECT_TRUE(got.lighting.material == want.lighting.material) << where << ": material";
  for (size_t l = 0; l < kMaxLights; ++l)
    EXPECT_TRUE(got.lighting.lights[l] == want.lighting.lights[l]) << where << ": light " << l;
  EXPECT_EQ(got.texgen.num_texgens, want.texgen.num_texgens) << where;
  for (size_t g = 0; g < kMaxTexGens; ++g)
    EXPECT_TRUE(got.texgen.texgens[g] == want.texgen.texgens[g]) << where << ": texgen " << g;
  EXPECT_TRUE(got.texgen.matrices == want.texgen.matrices) << where << ": texture matrices";
  for (size_t m = 0; m < kMaxTexMaps; ++m)
    EXPECT_TRUE(got.textures[m] == want.textures[m]) << where << ": texture map " << m;
}

std::vector<std::string> demo_scenes() {
  std::vector<std::string> out = test::json_files("scenes");
  for (const char* sub : {"scenes/ortho", "scenes/maps"})
    for (const std::string& s : test::json_files(sub)) out.push_back(s);
  out.push_back("scenes/gltf/blob.glb");
  return out;
}

class GxFifoScene : public ::testing::TestWithParam<std::string> {};

// Every pass of every material, each written alone and read back by the stream reader, decodes
// to the state the emulator runs (in the form the registers hold it), for every variant the
// scene renders.
TEST_P(GxFifoScene, EveryPassDecodesToTheStateTheEmulatorRuns) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  const PathInfo& info = find_path("gx");
  int variants = 0;
  for (const VariantInfo& v : info.variants) {
    if (!info.refusal(scene, v.name).empty()) continue;
    ++variants;
    const GxVariant gv = parse_gx_variant(v.name);
    const ScenePrograms programs = scene_programs_for(scene, gv, "");
    for (size_t m = 0; m < programs.by_material.size(); ++m) {
      const TextureObject lut = lobe_lut(scene.materials[m], gv.lut_size);
      for (const PassProgram& p : programs.by_material[m]) {
        const std::string where = GetParam() + " " + v.name + " " + p.name;
        std::array<const TextureObject*, kMaxTexMaps> textures{};
        std::array<u32, kMaxTexMaps> addresses{};
        for (size_t map = 0; map < kMaxTexMaps; ++map) {
          textures[map] =
              p.state.textures[map] ? &*p.state.textures[map] : (map == 0 ? &lut : nullptr);
          addresses[map] = 0x01040000 + 0x20000 * static_cast<u32>(map);
        }
        CommandStream out;
        write_pass_cp(out, p.state);
        write_pass_xf(out, p.state);
        write_pass_bp(out, p.state, textures, addresses);
        RegisterFile regs;
        read_stream(out.bytes(), regs, where);
        const DecodedPass d = decode_pass(regs);
        expect_same_state(d.state, canonical_state(p.state, &lut), where);
        for (size_t map = 0; map < kMaxTexMaps; ++map) {
          if (textures[map]) EXPECT_EQ(d.texture_addresses[map], addresses[map]) << where;
        }
      }
    }
  }
  EXPECT_GT(variants, 0) << "no gx variant renders " << GetParam();
}

// The whole frame of the default variant, walked as Dolphin's command processor walks it: the
// container reads back identical; every draw decodes to its pass's state, with the textures its
// stages fetch sent before it, at the addresses the registers point to, byte for byte the tiles
// the emulator samples, and its vertices the stream the emulator's XF reads; one clearing copy
// first, one copy to the XFB last.
TEST_P(GxFifoScene, FrameDrawsEveryPassWithItsStateTexturesAndVertices) {
  const Scene scene = load_scene(test::source_dir() / GetParam());
  const GxVariant gv = parse_gx_variant("t=vertex");
  const ScenePrograms programs = scene_programs_for(scene, gv, "");
  const FifoLog log = record_frames(scene, {{gv, &programs}}, {320, 240});
  const std::vector<u8> bytes = write_fifo_log(log);
  EXPECT_TRUE(read_fifo_log(bytes, "frame.dff") == log);
  ASSERT_EQ(log.frames.size(), 1u);

  // The draws the frame must hold, in order: per pass, per material, per object, per chunk.
  struct Expected {
    const GxState* state;
    size_t material, object, first;
  };
  std::vector<Expected> expected;
  for (int pass = 0; pass < programs.passes(); ++pass)
    for (size_t m = 0; m < programs.by_material.size(); ++m) {
      if (static_cast<size_t>(pass) >= programs.by_material[m].size()) continue;
      for (size_t o = 0; o < scene.objects.size(); ++o) {
        if (static_cast<size_t>(scene.objects[o].material) != m) continue;
        const size_t n = scene.objects[o].mesh.triangles.size() * 3;
        for (size_t first = 0; first < n; first += 65535)
          expected.push_back(
              {&programs.by_material[m][static_cast<size_t>(pass)].state, m, o, first});
      }
    }
  const SceneView view = SceneView::of(scene);
  std::vector<VertexStream> streams;
  for (const SceneObject& o : scene.objects) streams.push_back(make_vertex_stream(scene, o, view));

  const FifoFrame& frame = log.frames[0];
  RegisterFile regs;
  size_t k = 0;
  const StreamEvents events =
      read_stream(frame.fifo, regs, GetParam(), [&](const RegisterFile& r, const StreamDraw& d) {
        ASSERT_LT(k, expected.size());
        const Expected& e = expected[k++];
        const std::string where = GetParam() + " draw " + std::to_string(k - 1);
        const TextureObject lut = lobe_lut(scene.materials[e.material], gv.lut_size);
        DecodedPass dp = decode_pass(r, d.vat);
        const GxState want = canonical_state(*e.state, &lut);
        // A map an earlier pass loaded keeps its registers; the pass test above checks that each
        // pass writes exactly its own maps.
        for (size_t m = 0; m < kMaxTexMaps; ++m)
          if (!want.textures[m]) dp.state.textures[m].reset();
        expect_same_state(dp.state, want, where);
        for (int st = 0; st < dp.state.tev.num_stages; ++st) {
          const u8 map = dp.state.tev.stages[static_cast<size_t>(st)].texmap;
          if (map == kTexMapNull) continue;
          const auto& t = e.state->textures[map];
          const std::vector<u8>& tiles = t ? t->data : lut.data;
          const u32 address = dp.texture_addresses[map];
          bool found = false;
          for (const MemoryUpdate& u : frame.updates)
            if (u.address == address && u.fifo_position <= d.offset) found |= u.data == tiles;
          EXPECT_TRUE(found) << where << ": map " << int{map}
                             << " has no memory update of its tiles";
        }
        // Vertices: the position of every vertex, and the whole first vertex's size.
        const TriangleMesh& mesh = scene.objects[e.object].mesh;
        EXPECT_EQ(d.vertex_size, vertex_size(sent_attributes(*e.state), e.state->texcoord_formats));
        for (u32 v = 0; v < d.count; ++v) {
          const size_t flat = e.first + v;
          const u32 index = mesh.triangles[flat / 3][static_cast<int>(flat % 3)];
          for (int c = 0; c < 3; ++c) {
            const u8* p = &frame.fifo[d.offset + v * d.vertex_size + 4 * static_cast<size_t>(c)];
            const u32 w = (u32{p[0]} << 24) | (u32{p[1]} << 16) | (u32{p[2]} << 8) | p[3];
            ASSERT_EQ(bits_float(w), streams[e.object].position[index][c])
                << where << " vertex " << v;
          }
        }
      });
  EXPECT_EQ(k, expected.size());
  ASSERT_EQ(events.copies.size(), 2u);
  EXPECT_EQ(events.copies[0] >> 11 & 1, 1u);  // clears
  EXPECT_EQ(events.copies[0] >> 14 & 1, 0u);  // to a texture
  EXPECT_EQ(events.copies[1] >> 11 & 1, 1u);
  EXPECT_EQ(events.copies[1] >> 14 & 1, 1u);  // to the XFB
  EXPECT_EQ(regs.bp[bp::kCopyDestination] << 5, kXfbAddress);
  // Every memory update is 32-byte aligned and clear of the XFB, the clear target and the ring.
  for (const MemoryUpdate& u : frame.updates) {
    EXPECT_EQ(u.address % 32, 0u);
    EXPECT_GE(u.address, kTextureBase);
    EXPECT_LE(u.address + u.data.size(), kTextureEnd);
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GxFifoScene, ::testing::ValuesIn(demo_scenes()),
                         [](const auto& info) { return test::scene_param_name(info.param); });

// The header snapshot is GX_Init's state: GxState{} read back, and GX_Init's own registers.
TEST(GxFifoLog, HeaderSnapshotIsGxInitsState) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const GxVariant gv = parse_gx_variant("t=vertex");
  const ScenePrograms programs = scene_programs_for(scene, gv, "");
  const FifoLog log = record_frames(scene, {{gv, &programs}}, {320, 240});
  RegisterFile regs;
  regs.bp = log.bp;
  for (size_t k = 0; k < 4; ++k) regs.tev_konst[k] = {log.bp[0xe0 + 2 * k], log.bp[0xe1 + 2 * k]};
  regs.cp = log.cp;
  regs.xf_memory = log.xf_memory;
  regs.xf_registers = log.xf_registers;
  expect_same_state(decode_pass(regs).state, canonical_state(GxState{}, nullptr), "header");
  EXPECT_EQ(log.bp[0x00], 0x4001u);    // genmode: 1 texgen, 1 stage, GX_CULL_BACK
  EXPECT_EQ(log.bp[0x41], 0x4BCu);     // GX_BM_NONE, SRCALPHA, INVSRCALPHA, dither, updates
  EXPECT_EQ(log.bp[0x40], 0x17u);      // GX_SetZMode(GX_ENABLE, GX_LEQUAL, GX_TRUE)
  EXPECT_EQ(log.bp[0x43], 0x40u);      // RGB8_Z24, z compare before texturing
  EXPECT_EQ(log.bp[0x53], 0x595000u);  // GX_SetCopyFilter's default vertical filter [L1965]
  EXPECT_EQ(log.bp[0x54], 0x15u);
  EXPECT_EQ(log.xf_registers[0x12], 1u);  // dual texture transform on [__GX_InitRevBits]
  EXPECT_EQ(log.bp[0xfe], 0xffffffu);     // the BP mask reads all ones
}

// The Dolphin tests' layout (for_dolphin_judging): the judged frames as recorded, between a
// blank lead-in and kDolphinTrailingCopies blank frames, each blank one GX_Init's registers, a
// clear and the display copy that ends a frame: no draw, no memory update, one EFB copy, and
// that copy the drawn frames' own (the XFB, with clear).
TEST(GxFifoLog, JudgedFramesSitBetweenBlankFramesThatEndInTheDisplayCopy) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const GxVariant a = parse_gx_variant("t=vertex"), b = parse_gx_variant("t=vertex:lut=32");
  const ScenePrograms pa = scene_programs_for(scene, a, ""), pb = scene_programs_for(scene, b, "");
  const FrameSize size{160, 120};
  const FifoLog recorded = record_frames(scene, {{a, &pa}, {b, &pb}}, size);
  const FifoLog judged = for_dolphin_judging(recorded, size);
  ASSERT_EQ(judged.frames.size(), 1u + 2u + static_cast<size_t>(kDolphinTrailingCopies));
  EXPECT_EQ(judged.frames[1], recorded.frames[0]);
  EXPECT_EQ(judged.frames[2], recorded.frames[1]);
  const FifoFrame& blank = judged.frames[0];
  for (size_t i = 3; i < judged.frames.size(); ++i) EXPECT_EQ(judged.frames[i], blank) << i;
  EXPECT_TRUE(blank.updates.empty());
  RegisterFile blank_regs, drawn_regs;
  const StreamEvents blank_events = read_stream(blank.fifo, blank_regs, "blank");
  const StreamEvents drawn_events = read_stream(recorded.frames[0].fifo, drawn_regs, "drawn");
  EXPECT_TRUE(blank_events.draws.empty());
  EXPECT_FALSE(drawn_events.draws.empty());
  ASSERT_EQ(blank_events.copies.size(), 1u);
  ASSERT_FALSE(drawn_events.copies.empty());
  EXPECT_EQ(blank_events.copies.back(), drawn_events.copies.back());
  // The frame ends at the copy's trigger, as Dolphin's FIFO player requires of a frame.
  for (const std::vector<u8>* fifo : {&blank.fifo, &recorded.frames[0].fifo})
    EXPECT_EQ((*fifo)[fifo->size() - 4], bp::kCopyTrigger) << "the last command: the trigger";
  for (u8 r : {bp::kCopySourceTopLeft, bp::kCopySourceSize, bp::kCopyDestination})
    EXPECT_EQ(blank_regs.bp[r], drawn_regs.bp[r]) << "BP " << int(r);
}

// The container: header fields at the offsets FifoDataFile.cpp gives, read back by the reader.
TEST(GxFifoLog, ContainerHasDolphinsLayout) {
  FifoLog log;
  log.bp[0x41] = 0x123;
  FifoFrame f;
  f.fifo = {0x61, 0x41, 0x00, 0x00, 0x01};
  f.updates.push_back({5, 0x01040000, kMemoryUpdateTexture, {1, 2, 3}});
  log.frames = {f, f};
  const std::vector<u8> b = write_fifo_log(log);
  auto u32_at = [&](size_t at) {
    return u32{b[at]} | u32{b[at + 1]} << 8 | u32{b[at + 2]} << 16 | u32{b[at + 3]} << 24;
  };
  EXPECT_EQ(u32_at(0), 0x0D01F1F0u);
  EXPECT_EQ(u32_at(4), 5u);
  EXPECT_EQ(u32_at(20), 256u);                         // bpMemSize
  EXPECT_EQ(u32_at(56), 88u);                          // xfRegsSize
  EXPECT_EQ(u32_at(60), 128u);                         // frameListOffset
  EXPECT_EQ(u32_at(68), 2u);                           // frameCount
  EXPECT_EQ(u32_at(72), 0u);                           // flags: GameCube (4:3)
  EXPECT_EQ(u32_at(84), 1024u * 1024);                 // texMemSize
  EXPECT_EQ(u32_at(88), 0x01800000u);                  // mem1_size
  EXPECT_EQ(u32_at(92), 0x04000000u);                  // mem2_size
  EXPECT_EQ(u32_at(128 + 2 * 64 + 4 * 0x41), 0x123u);  // BP snapshot right after the frame list
  EXPECT_TRUE(read_fifo_log(b, "x.dff") == log);
  std::vector<u8> cut(b.begin(), b.end() - 2);
  EXPECT_THROW(read_fifo_log(cut, "x.dff"), InputError);
  std::vector<u8> wrong = b;
  wrong[0] = 0;
  EXPECT_THROW(read_fifo_log(wrong, "x.dff"), InputError);
}

// A long draw is split at 65,535 vertices (a multiple of 3: no triangle is cut).
TEST(GxFifoLog, DrawsSplitAt65535Vertices) {
  // The demo sphere with its triangles listed many times over: one object of > 65,535 vertices.
  Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  TriangleMesh& mesh = scene.objects[0].mesh;
  const auto once = mesh.triangles;
  while (mesh.triangles.size() * 3 <= 70000)
    mesh.triangles.insert(mesh.triangles.end(), once.begin(), once.end());
  const size_t vertices = scene.objects[0].mesh.triangles.size() * 3;
  ASSERT_GT(vertices, 65535u);
  const GxVariant gv = parse_gx_variant("t=vertex");
  const ScenePrograms programs = scene_programs_for(scene, gv, "");
  const FifoLog log = record_frames(scene, {{gv, &programs}}, {64, 64});
  RegisterFile regs;
  const StreamEvents ev = read_stream(log.frames[0].fifo, regs, "big");
  size_t total = 0;
  for (const StreamDraw& d : ev.draws) {
    EXPECT_LE(d.count, 65535u);
    EXPECT_EQ(d.count % 3, 0u);
    total += d.count;
  }
  EXPECT_EQ(total, vertices * static_cast<size_t>(programs.passes()));
}

// ---- The export command.

TEST(GxFifoCli, ExportWritesALogDolphinDumpsAndRefusesWhatTheConsoleCannotShow) {
  const std::string scene = (test::source_dir() / "scenes/backlit_sphere.json").string();
  test::TempDir dir;
  const fs::path dff = dir / "frame.dff";
  const test::RunResult ok = test::run_ltrender(
      "export gx " + scene + " --format dff --width 320 --height 240 -o " + dff.string());
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  std::ifstream in(dff, std::ios::binary);
  const std::vector<u8> bytes((std::istreambuf_iterator<char>(in)), {});
  const FifoLog log = read_fifo_log(bytes, dff.string());
  // The frame and the copies that make Dolphin show it.
  ASSERT_EQ(log.frames.size(), 1u + kDolphinTrailingCopies);
  for (const auto& copy : log.frames) EXPECT_TRUE(copy == log.frames[0]);

  // The exported C read back with --program draws the very same frame, byte for byte.
  const fs::path c = dir / "exported.c", replayed = dir / "replayed.dff";
  ASSERT_EQ(test::run_ltrender("export gx " + scene + " -o " + c.string()).exit_code, 0);
  const test::RunResult rp =
      test::run_ltrender("export gx " + scene + " --format dff --program " + c.string() +
                         " --width 320 --height 240 -o " + replayed.string());
  ASSERT_EQ(rp.exit_code, 0) << rp.err;
  std::ifstream in2(replayed, std::ios::binary);
  EXPECT_TRUE(std::vector<u8>((std::istreambuf_iterator<char>(in2)), {}) == bytes);

  // Wider than the EFB, or not a multiple of 16: one line naming the key and the size, nothing
  // written.
  for (const std::string size :
       {"--width 656 --height 240", "--width 328 --height 240", "--width 320 --height 530"}) {
    const fs::path bad = dir / "bad.dff";
    const test::RunResult r =
        test::run_ltrender("export gx " + scene + " --format dff " + size + " -o " + bad.string());
    EXPECT_EQ(r.exit_code, 2) << size;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    const std::string key = size.find("530") != std::string::npos ? "--height" : "--width";
    EXPECT_NE(r.err.find(key), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(bad)) << size;
  }
  const test::RunResult missing = test::run_ltrender(
      "export gx " + (dir / "none.json").string() + " --format dff -o " + (dir / "m.dff").string());
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_EQ(std::count(missing.err.begin(), missing.err.end(), '\n'), 1) << missing.err;
  EXPECT_FALSE(fs::exists(dir / "m.dff"));
  // The extension follows the format; an unknown format is refused.
  EXPECT_EQ(test::run_ltrender("export gx " + scene + " --format dff -o " + (dir / "x.c").string())
                .exit_code,
            2);
  EXPECT_EQ(
      test::run_ltrender("export gx " + scene + " --format png -o " + (dir / "x.png").string())
          .exit_code,
      2);
  EXPECT_FALSE(fs::exists(dir / "x.c"));
}

}  // namespace
}  // namespace lt::gx::fifo

namespace lt::gx::fifo {
namespace {

// `export gx --format dff --frames N`: the camera path's N frames in one log, each its own (the
// camera moves), with frame 0 in front once more and the last frame 3 times after
// (for_dolphin_animation); frame 0 is the one-frame export's frame.
TEST(GxFifoExport, FramesAlongTheCameraPathInOneLog) {
  test::TempDir dir;
  const std::string scene = (test::source_dir() / "scenes/backlit_sphere.json").string();
  const fs::path anim = dir / "anim.dff", one = dir / "one.dff";
  const std::string size = " --format dff --width 160 --height 120 -o ";
  test::RunResult r =
      test::run_ltrender("export gx " + scene + " --frames 3" + size + anim.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  r = test::run_ltrender("export gx " + scene + size + one.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  auto read = [](const fs::path& f) {
    std::ifstream in(f, std::ios::binary);
    const std::vector<u8> bytes((std::istreambuf_iterator<char>(in)), {});
    return read_fifo_log(bytes, f.string());
  };
  const FifoLog a = read(anim), o = read(one);
  ASSERT_EQ(a.frames.size(), 1u + 3u + static_cast<size_t>(kDolphinTrailingCopies));
  EXPECT_EQ(a.frames[0], a.frames[1]);
  EXPECT_EQ(a.frames[1], o.frames[0]);
  EXPECT_NE(a.frames[1].fifo, a.frames[2].fifo);
  EXPECT_NE(a.frames[2].fifo, a.frames[3].fifo);
  for (size_t i = 4; i < a.frames.size(); ++i) EXPECT_EQ(a.frames[i], a.frames[3]) << i;
  // --frames is for a dff, and not with a program file (one frame's state): one line, exit 2.
  r = test::run_ltrender("export gx " + scene + " --frames 2 -o " + (dir / "x.c").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.c"));
}

}  // namespace
}  // namespace lt::gx::fifo
