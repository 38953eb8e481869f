// GX program files (gx.md §1): the parser, the interpreter that turns libogc calls into GX state
// (checked against libogc's own encodings), the printer's round trip, and every kind of bad
// file, each refused with file:line:column.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gx/program/interpreter.h"
#include "gx/program/parser.h"
#include "gx/program/pass_programs.h"
#include "gx/program/printer.h"
#include "gx_test_programs.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_budget.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::gx {
namespace {

const char* const kExample = test_programs::kFlatColour;

GxState run(const std::string& text) {
  const ProgramFile f = parse_program(text, "test.c");
  return run_program(f.file, {&f.top_level});
}

TEST(GxProgram, ExampleSetsTheStateLibogcWould) {
  const GxState st = run(kExample);
  EXPECT_EQ(st.lighting.num_channels, 1);
  EXPECT_FALSE(st.lighting.control[0].lighting);
  EXPECT_FALSE(st.lighting.control[2].lighting) << "GX_COLOR0A0 sets the alpha control too";
  EXPECT_EQ(st.lighting.material[0], (Color8{200, 120, 40, 255}));
  const TevStage& s = st.tev.stages[0];
  EXPECT_EQ(s.texmap, kTexMapNull);
  EXPECT_EQ(s.channel, 4);
  EXPECT_EQ(s.color.a, 15);  // GX_CC_ZERO
  EXPECT_EQ(s.color.b, 10);  // GX_CC_RASC
  EXPECT_EQ(s.color.c, 14);  // GX_CC_KONST
  EXPECT_EQ(s.konst_color_sel, 0x0C);
  EXPECT_EQ(st.tev.konst[0], (Color8{128, 64, 255, 255}));
  EXPECT_TRUE(s.color.clamp);
}

TEST(GxProgram, StartsFromGxInit) {
  const GxState st = run("");
  // GX_Init [OGC gx.c __GX_InitGX]: 1 stage, REPLACE, KCSEL 1/4 everywhere, 1 texgen, no
  // channels, blending off, stage 0 reading TEXCOORD0/TEXMAP0/COLOR0A0.
  EXPECT_EQ(st.tev.num_stages, 1);
  EXPECT_EQ(st.tev.stages[0].color.d, 8);                                   // GX_CC_TEXC
  for (const TevStage& s : st.tev.stages) EXPECT_EQ(s.konst_color_sel, 6);  // GX_TEV_KCSEL_1_4
  EXPECT_EQ(st.texgen.num_texgens, 1);
  EXPECT_EQ(st.lighting.num_channels, 0);
  EXPECT_EQ(st.blend.type, 0);
  EXPECT_EQ(st.tev.stages[0].texmap, 0);
  EXPECT_EQ(st.tev.stages[9].texmap, kTexMapNull);
}

TEST(GxProgram, CompareOpsAreEncodedAsLibogcDoes) {
  // GX_SetTevColorOp with GX_TEV_COMP_GR16_EQ (11): bias 3, scale (11 >> 1) & 3 = 1, op 1; the
  // bias and scale arguments are ignored [OGC gx.c GX_SetTevColorOp].
  const GxState st = run(
      "GX_SetTevColorOp(GX_TEVSTAGE2, GX_TEV_COMP_GR16_EQ, GX_TB_ADDHALF, GX_CS_SCALE_4, GX_FALSE, "
      "GX_TEVREG1);");
  const TevCombiner& c = st.tev.stages[2].color;
  EXPECT_EQ(c.bias, 3);
  EXPECT_EQ(c.scale, 1);
  EXPECT_EQ(c.op, 1);
  EXPECT_FALSE(c.clamp);
  EXPECT_EQ(c.dest, 2);
}

TEST(GxProgram, LightObjectsFollowLibogcHelpers) {
  const GxState st = run(R"(GXLightObj l;
GX_InitLightPos(&l, 1.0f, 2, -3.5);
GX_InitLightDir(&l, 0.0f, 0.0f, 1.0f);
GX_InitLightSpot(&l, 90.0f, GX_SP_OFF);
GX_InitLightDistAttn(&l, 2.0f, 0.5f, GX_DA_STEEP);
GX_InitLightColor(&l, (GXColor){10, 20, 30, 40});
GX_LoadLightObj(&l, GX_LIGHT3);
GX_InitLightPos(&l, 9, 9, 9);
)");
  const XfLight& x = st.lighting.lights[3];
  EXPECT_EQ(x.position, glm::vec3(1, 2, -3.5f)) << "loaded before the later GX_InitLightPos";
  EXPECT_EQ(x.direction, glm::vec3(0, 0, -1)) << "GX_InitLightDir stores the negated direction";
  EXPECT_EQ(x.a, (std::array<float, 3>{1, 0, 0}));
  // STEEP: k = (1, 0, (1 - b) / (b r^2)) = (1, 0, 0.25) [OGC gx.c L4695-4730].
  EXPECT_EQ(x.k, (std::array<float, 3>{1, 0, 0.25f}));
  EXPECT_EQ(x.color, (Color8{10, 20, 30, 40}));
}

TEST(GxProgram, TexturesComeFromNamedArraysInTileOrder) {
  const GxState st = run(R"(static u8 lut[32] ATTRIBUTE_ALIGNED(32) = {
  0, 36, 73, 109, 146, 182, 219, 255, 0, 0, 0, 0, 0, 0, 0, 0,
  0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0 };
GXTexObj t;
GX_InitTexObj(&t, lut, 8, 1, GX_TF_I8, GX_CLAMP, GX_REPEAT, GX_FALSE);
GX_LoadTexObj(&t, GX_TEXMAP2);
)");
  ASSERT_TRUE(st.textures[2].has_value());
  EXPECT_EQ(st.textures[2]->width, 8);
  EXPECT_EQ(st.textures[2]->wrap_t, 1);
  EXPECT_EQ(st.textures[2]->data.size(), 32u);
  EXPECT_EQ(st.textures[2]->data[7], 255);
  EXPECT_FALSE(st.textures[0].has_value());
}

// Every kind of bad file: one InputError naming file:line:column and what is wrong.
struct BadProgramCase {
  const char* what;
  const char* text;
  const char* where;    // "line:column"
  const char* message;  // a part of the message
};

class GxBadProgram : public ::testing::TestWithParam<BadProgramCase> {};

TEST_P(GxBadProgram, IsRefusedWithFileLineAndColumn) {
  const BadProgramCase& c = GetParam();
  try {
    const ProgramFile f = parse_program(c.text, "bad.c");
    file_programs(f);
    FAIL() << c.what << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "bad.c");
    EXPECT_EQ(e.where(), c.where) << e.what();
    EXPECT_NE(e.what_only().find(c.message), std::string::npos) << e.what();
  }
}

const BadProgramCase kBad[] = {
    {"unknown_call", "GX_SetNumChans(1);\nGX_Frobnicate(1);\n", "2:1", "not modelled"},
    {"not_gx_call", "foo(1);\n", "1:1", "unknown call foo"},
    {"wrong_argument_count", "GX_SetNumChans(1, 2);\n", "1:1", "expected 1 arguments, found 2"},
    {"unknown_name", "GX_SetNumChans(GX_THREE);\n", "1:16", "unknown name GX_THREE"},
    {"name_of_wrong_group",
     "GX_SetTevColorIn(GX_TEVSTAGE0, GX_CA_TEXA, GX_CC_ZERO, GX_CC_ZERO, GX_CC_ZERO);\n", "1:32",
     "an alpha input (GX_CA_*), expected a colour input"},
    {"value_out_of_range", "GX_SetTevColorIn(GX_TEVSTAGE0, 16, 15, 15, 15);\n", "1:32",
     "out of range: 16"},
    {"colour_out_of_range", "GX_SetTevKColor(GX_KCOLOR0, (GXColor){256, 0, 0, 0});\n", "1:29",
     "colour component out of range: 256"},
    {"unmodelled_call", "GX_LoadPosMtxImm(m, GX_PNMTX0);\n", "1:1", "matrices come from the scene"},
    {"unmodelled_texgen_source",
     "GX_SetTexCoordGen(GX_TEXCOORD0, GX_TG_MTX2x4, GX_TG_BINRM, GX_IDENTITY);\n", "1:47",
     "not modelled"},
    {"missing_semicolon", "GX_SetNumChans(1)\nGX_SetNumTevStages(1);\n", "2:1", "expected ';'"},
    {"undeclared_light", "GX_InitLightPos(&nolight, 0, 0, 0);\n", "1:17",
     "&name of a declared GXLightObj"},
    {"float_for_a_name", "GX_SetNumTevStages(1.5);\n", "1:20", "expected a number"},
    {"bad_character", "GX_SetNumChans(1); @\n", "1:20", "unexpected character '@'"},
    // Not printed raw: one byte of a UTF-8 character would garble the message.
    {"non_ascii_byte", "GX_SetNumChans(1); \xC3\xA9\n", "1:20", "unexpected character 0xC3"},
    {"unterminated_comment", "/* no end\nGX_SetNumChans(1);\n", "1:1", "unterminated comment"},
    {"badly_named_function", "void setup(void) {\n  GX_SetNumChans(1);\n}\n", "1:1",
     "ltrender_<material>_pass<N>"},
    {"matrix_beyond_float", "Mtx m = {{1e39, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};\n", "1:11",
     "out of float range"},
    {"too_many_bytes", "u8 a[2] = {1, 2, 3};\n", "1:1", "declares 2 bytes but lists 3"},
    // The YUV and depth-only formats keep no RGB colour for the TEV's output.
    {"unmodelled_pixel_format", "GX_SetPixelFmt(GX_PF_Y8, GX_ZC_LINEAR);\n", "1:16",
     "pixel format not modelled"},
};

INSTANTIATE_TEST_SUITE_P(Cases, GxBadProgram, ::testing::ValuesIn(kBad),
                         [](const auto& info) { return std::string(info.param.what); });

// fail_arg takes the argument's index: 8 (one past the end) read outside the call's arguments
// (found by ./test.sh --sanitize), 5 named the wrap mode for a bad format.
// GX_InitTexObj with mipmaps and GX_InitTexObjLOD as libogc writes them [OGC gx.c L3236-3247,
// L3310-3334]: 64 bytes hold an 8x4 I8 level (one 32-byte tile) and its 4x2 level (one tile).
TEST(GxProgram, MipmappedTexturesTakeTheirLevelsAndLodFields) {
  const GxState st =
      run("u8 a[64] = {0};\nGXTexObj t;\n"
          "GX_InitTexObj(&t, a, 8, 4, GX_TF_I8, GX_REPEAT, GX_CLAMP, GX_TRUE);\n"
          "GX_InitTexObjLOD(&t, GX_NEAR_MIP_LIN, GX_NEAR, 0.0, 1.0, -1.0, GX_FALSE, GX_TRUE, "
          "GX_ANISO_2);\n"
          "GX_LoadTexObj(&t, GX_TEXMAP0);\n");
  ASSERT_TRUE(st.textures[0].has_value());
  const TextureObject& t = *st.textures[0];
  EXPECT_EQ(t.levels, 2);
  EXPECT_EQ(t.data.size(), 64u);
  EXPECT_FALSE(t.linear);  // mag GX_NEAR
  ASSERT_TRUE(t.lod.has_value());
  EXPECT_EQ(t.lod->min_filter, 2);  // GX_NEAR_MIP_LIN through _gx2HWFiltConv
  EXPECT_EQ(t.lod->bias, -32);      // -1.0 in s2.5
  EXPECT_EQ(t.lod->max_lod, 16);    // 1.0 in u4.4
  EXPECT_EQ(t.lod->max_aniso, 1);
  EXPECT_FALSE(t.lod->diagonal);  // edgelod GX_TRUE
}

// fail_arg takes the argument's index: 8 (one past the end) read outside the call's arguments
// (found by ./test.sh --sanitize), 5 named the wrap mode for a bad format.
TEST(GxProgram, MipmapsOnASizeThatDoesNotHalveAreRefusedAtTheWidth) {
  try {
    run("u8 a[64] = {0};\nGXTexObj t;\nGX_InitTexObj(&t, a, 6, 4, GX_TF_I8, GX_CLAMP, GX_CLAMP, "
        "GX_TRUE);\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("must be a power of two, found 6x4"), std::string::npos)
        << e.what();
    EXPECT_NE(e.what_only().find("argument 3:"), std::string::npos) << e.what();
  }
}

TEST(GxProgram, ALodRangePastTheArraysLevelsIsRefusedAtTheLoad) {
  try {
    // 32 bytes: level 0 only; max LOD 1.0 reads level 1.
    run("u8 a[32] = {0};\nGXTexObj t;\nGX_InitTexObj(&t, a, 8, 4, GX_TF_I8, GX_CLAMP, GX_CLAMP, "
        "GX_TRUE);\nGX_InitTexObjLOD(&t, GX_LIN_MIP_LIN, GX_LINEAR, 0.0, 1.0, 0.0, GX_FALSE, "
        "GX_TRUE, GX_ANISO_1);\nGX_LoadTexObj(&t, GX_TEXMAP0);\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("reads 2 levels, a holds 1 (32 bytes)"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.where().substr(0, 2), "5:") << e.what();
  }
}

// libogc's single-field setters [OGC gx.c L3353-3407] each write the field GX_InitTexObjLOD
// writes with the same value, and nothing else: from one GX_InitTexObjLOD, a setter gives the
// object GX_InitTexObjLOD's with that one argument changed; all of them together give the
// object a second GX_InitTexObjLOD with every argument changed. The array is an 8x8 I8 chain of
// 4 levels (64 + 32 + 32 + 32 bytes), so a max LOD up to 3 loads.
struct LodArgs {
  std::string min_filter = "GX_LIN_MIP_LIN", mag_filter = "GX_LINEAR", min_lod = "0.5",
              max_lod = "1.0", bias = "0.0", bias_clamp = "GX_FALSE", edge = "GX_TRUE",
              aniso = "GX_ANISO_1";
  std::string call() const {
    return "GX_InitTexObjLOD(&t, " + min_filter + ", " + mag_filter + ", " + min_lod + ", " +
           max_lod + ", " + bias + ", " + bias_clamp + ", " + edge + ", " + aniso + ");\n";
  }
};
TextureObject lod_texture(const std::string& calls) {
  const GxState st =
      run("u8 a[160] = {0};\nGXTexObj t;\n"
          "GX_InitTexObj(&t, a, 8, 8, GX_TF_I8, GX_CLAMP, GX_CLAMP, GX_TRUE);\n" +
          calls + "GX_LoadTexObj(&t, GX_TEXMAP0);\n");
  EXPECT_TRUE(st.textures[0].has_value());
  return st.textures[0].value_or(TextureObject{});
}

TEST(GxProgram, EachLodSetterWritesWhatGxInitTexObjLodWrites) {
  const LodArgs base;
  struct Setter {
    std::string call;
    void (*change)(LodArgs&);
  };
  const Setter setters[] = {
      {"GX_InitTexObjMinLOD(&t, 0.25);\n", [](LodArgs& a) { a.min_lod = "0.25"; }},
      {"GX_InitTexObjMaxLOD(&t, 2.5);\n", [](LodArgs& a) { a.max_lod = "2.5"; }},
      {"GX_InitTexObjLODBias(&t, -1.5);\n", [](LodArgs& a) { a.bias = "-1.5"; }},
      {"GX_InitTexObjBiasClamp(&t, GX_TRUE);\n", [](LodArgs& a) { a.bias_clamp = "GX_TRUE"; }},
      {"GX_InitTexObjEdgeLOD(&t, GX_FALSE);\n", [](LodArgs& a) { a.edge = "GX_FALSE"; }},
      {"GX_InitTexObjMaxAniso(&t, GX_ANISO_4);\n", [](LodArgs& a) { a.aniso = "GX_ANISO_4"; }},
      {"GX_InitTexObjFilterMode(&t, GX_NEAR_MIP_NEAR, GX_NEAR);\n",
       [](LodArgs& a) {
         a.min_filter = "GX_NEAR_MIP_NEAR";
         a.mag_filter = "GX_NEAR";
       }},
  };
  LodArgs all = base;
  std::string every_setter;
  for (const Setter& s : setters) {
    SCOPED_TRACE(s.call);
    LodArgs changed = base;
    s.change(changed);
    s.change(all);
    every_setter += s.call;
    const TextureObject by_setter = lod_texture(base.call() + s.call);
    const TextureObject by_lod = lod_texture(changed.call());
    ASSERT_TRUE(by_setter.lod.has_value());
    EXPECT_TRUE(by_setter.lod == by_lod.lod);
    EXPECT_EQ(by_setter.linear, by_lod.linear);
    EXPECT_FALSE(by_setter.lod == lod_texture(base.call()).lod) << "the setter changed nothing";
  }
  const TextureObject by_setters = lod_texture(base.call() + every_setter);
  const TextureObject by_lod = lod_texture(all.call());
  EXPECT_TRUE(by_setters.lod == by_lod.lod);
  EXPECT_FALSE(by_setters.linear);
  // The fields as libogc's conversions give them, worked by hand.
  ASSERT_TRUE(by_setters.lod.has_value());
  EXPECT_EQ(by_setters.lod->min_lod, 4);   // 16 * 0.25
  EXPECT_EQ(by_setters.lod->max_lod, 40);  // 16 * 2.5
  EXPECT_EQ(by_setters.lod->bias, -48);    // 32 * -1.5
  EXPECT_TRUE(by_setters.lod->bias_clamp);
  EXPECT_TRUE(by_setters.lod->diagonal);     // !edgelod
  EXPECT_EQ(by_setters.lod->max_aniso, 2);   // GX_ANISO_4
  EXPECT_EQ(by_setters.lod->min_filter, 1);  // GX_NEAR_MIP_NEAR through _gx2HWFiltConv
  // The clamps: a bias of 4.0 is stored as 3.99 (127), a min LOD above 10 as 10 (160); without a
  // mip filter the range reads level 0 alone, so the load takes it.
  const TextureObject clamped = lod_texture(
      base.call() +
      "GX_InitTexObjFilterMode(&t, GX_LINEAR, GX_LINEAR);\nGX_InitTexObjLODBias(&t, 4.0);\n"
      "GX_InitTexObjMinLOD(&t, 12.0);\n");
  ASSERT_TRUE(clamped.lod.has_value());
  EXPECT_EQ(clamped.lod->bias, 127);
  EXPECT_EQ(clamped.lod->min_lod, 160);
}

// GX_REPEAT over a side that is not a power of two is refused at the load (the console masks the
// coordinate with the size minus one: not a repeat), whether GX_InitTexObj or a later
// GX_InitTexObjWrapMode asked for it; the same wrap over a power of two loads.
TEST(GxProgram, RepeatOverASideThatIsNotAPowerOfTwoIsRefusedAtTheLoad) {
  const std::string init =
      "u8 a[64] = {0};\nGXTexObj t;\n"
      "GX_InitTexObj(&t, a, 8, 6, GX_TF_I8, GX_REPEAT, GX_CLAMP, GX_FALSE);\n";
  EXPECT_TRUE(run(init + "GX_LoadTexObj(&t, GX_TEXMAP0);\n").textures[0].has_value());
  try {
    run(init +
        "GX_InitTexObjWrapMode(&t, GX_REPEAT, GX_REPEAT);\nGX_LoadTexObj(&t, GX_TEXMAP0);\n");
    FAIL() << "GX_REPEAT over 6 texels loaded";
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("t repeats in t (GX_REPEAT) over 6 texels of a: repeat needs a "
                                 "power of two"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.where().substr(0, 2), "5:") << e.what();
  }
}

TEST(GxProgram, UnmodelledTextureFormatsAreRefusedAtTheirArgument) {
  try {
    run("u8 a[32] = {0};\nGXTexObj t;\nGX_InitTexObj(&t, a, 8, 1, GX_TF_CI8, GX_CLAMP, GX_CLAMP, "
        "GX_FALSE);\n");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(e.what_only().find("a colour-indexed format needs GX_InitTexObjCI"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.where(), "3:28") << e.what();  // GX_TF_CI8 (GX_InitTexObjCI's, with its TLUT)
    EXPECT_NE(e.what_only().find("argument 5:"), std::string::npos) << e.what();
  }
}

// The printer's C reads back to the same calls: every generated program of every demo scene,
// printed and parsed, gives the same GX state.
TEST(GxProgram, PrintedProgramsParseBackToTheSameState) {
  for (const std::string& s : test::json_files("scenes")) {
    const Scene scene = load_scene(test::source_dir() / s);
    const GeneratedPrograms g = generate_programs(scene, GxVariant{});
    const std::string text = print_program(g.file);
    const ProgramFile back = parse_program(text, "printed.c");
    const auto a = file_programs(g.file), b = file_programs(back);
    ASSERT_EQ(a.size(), b.size()) << s;
    for (size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].name, b[i].name);
      EXPECT_TRUE(a[i].state.tev == b[i].state.tev) << s << " " << a[i].name;
      EXPECT_TRUE(a[i].state.lighting == b[i].state.lighting) << s << " " << a[i].name;
      EXPECT_TRUE(a[i].state.texgen == b[i].state.texgen) << s << " " << a[i].name;
      EXPECT_TRUE(a[i].state.textures == b[i].state.textures) << s << " " << a[i].name;
    }
  }
}

// A UTF-8 byte-order mark before the program (a Windows editor's) is skipped, as GCC skips it:
// the same state, and positions count from the character after it.
TEST(GxProgram, AByteOrderMarkIsSkippedAsGccSkipsIt) {
  const Scene scene = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const std::string text = print_program(generate_programs(scene, GxVariant{}).file);
  const auto a = file_programs(parse_program(text, "plain.c"));
  const auto b = file_programs(parse_program("\xEF\xBB\xBF" + text, "marked.c"));
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_TRUE(a[i].state.tev == b[i].state.tev) << a[i].name;
    EXPECT_TRUE(a[i].state.lighting == b[i].state.lighting) << a[i].name;
  }
  try {
    parse_program("\xEF\xBB\xBF@", "marked.c");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "1:1") << e.what();
  }
}

// The bar of the issue: one light's term (diffuse + translucency) in at most 3 TEV stages in one
// pass, and no texture beyond the LUT, on every demo scene and every variant that applies. An
// albedo map (scenes/albedo_checker.json) is not the term: it costs exactly one stage and one
// texture more (docs/maps.md "Albedo maps").
TEST(GxProgram, OneLightTakesAtMostThreeStagesInOnePass) {
  for (const std::string& s : test::json_files("scenes")) {
    const Scene scene = load_scene(test::source_dir() / s);
    const budget::Report r = gx_budget_scene(scene, "", "wii-tev");
    EXPECT_TRUE(r.fits()) << s;
    EXPECT_EQ(r.most("passes"), static_cast<int>(std::max<size_t>(1, scene.lights.size()))) << s;
    for (const budget::Item& p : r.items) {
      if (p.scope != budget::Scope::Pass) continue;
      int albedo = 0;
      for (const Material& m : scene.materials) albedo += m.name == p.material && m.albedo_map;
      EXPECT_LE(p.used("tev_stages"), 3 + albedo) << s << " " << p.name;
      EXPECT_LE(p.used("texture_maps"), 1 + albedo) << s << " " << p.name;
      EXPECT_LE(p.used("lights_per_channel"), 1) << s << " " << p.name;
    }
  }
}

TEST(GxProgram, BudgetCountsAFileAndFindsOverruns) {
  test::TempDir dir;
  const std::string file = (dir / "over.c").string();
  test::write_file(file, "GX_SetNumTevStages(17);\nGX_SetNumChans(2);\n");
  const budget::Report r = gx_budget_file(file, "wii-tev");
  EXPECT_FALSE(r.fits());
  EXPECT_EQ(r.first_overrun().rfind(file + ": ", 0), 0u) << r.first_overrun();
  EXPECT_NE(r.first_overrun().find("TEV stages: 17 > 16 (wii-tev)"), std::string::npos)
      << r.first_overrun();
  const auto j = nlohmann::json::parse(budget::to_json(r));
  EXPECT_EQ(j["items"][0]["resources"][0]["key"], "tev_stages");
  EXPECT_EQ(j["items"][0]["resources"][0]["used"], 17);
  EXPECT_EQ(j["fits"], false);
}

TEST(GxVariantParse, AcceptsTheGrammarAndRefusesTheRest) {
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex")), "t=vertex");
  EXPECT_EQ(parse_gx_variant("t=vertex:lut=37").lut_size, 37);
  EXPECT_EQ(to_string(parse_gx_variant("lut=64:t=texgen")), "t=texgen:lut=64");
  EXPECT_EQ(to_string(parse_gx_variant("lobe=xf-spec")), "lobe=xf-spec");
  // A declared light range reads back as the same double (a sweep row builds by its name).
  EXPECT_EQ(to_string(parse_gx_variant("light-range=0.1:t=vertex")), "t=vertex:light-range=0.1");
  EXPECT_EQ(*parse_gx_variant("lobe=xf-spec:light-range=2").light_range, 2.0);
  EXPECT_FALSE(parse_gx_variant("t=vertex").light_range);
  // The coverage axis: console spelled out, dolphin the default (its canonical name omits it).
  EXPECT_EQ(to_string(parse_gx_variant("coverage=console:t=vertex")), "t=vertex:coverage=console");
  EXPECT_EQ(parse_gx_variant("lobe=xf-spec:coverage=console").coverage, CoverageRule::Console);
  EXPECT_EQ(parse_gx_variant("t=vertex").coverage, CoverageRule::Dolphin);
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex:coverage=dolphin")), "t=vertex");
  // The mip axes: their canonical order after :map=, the bias as the shortest double.
  EXPECT_EQ(to_string(parse_gx_variant("wrap=repeat:mip-bias=-1.25:mip=near:t=vertex")),
            "t=vertex:mip=near:mip-bias=-1.25:wrap=repeat");
  EXPECT_EQ(parse_gx_variant("t=vertex:mip=lin").mip, GxVariant::Mip::Linear);
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex:mip-bias=0:mip=lin:wrap=clamp")),
            "t=vertex:mip=lin");
  // Diagonal LOD after the bias; edge, the default, omitted.
  EXPECT_EQ(to_string(parse_gx_variant("mip-lod=diagonal:mip=near:mip-bias=-0.5:t=vertex")),
            "t=vertex:mip=near:mip-bias=-0.5:mip-lod=diagonal");
  EXPECT_EQ(to_string(parse_gx_variant("t=vertex:mip=lin:mip-lod=edge")), "t=vertex:mip=lin");
  for (const char* bad :
       {"t=vertex:mip=trilinear", "t=vertex:mip-bias=1", "t=vertex:mip=lin:mip-bias=4",
        "t=vertex:mip=lin:mip-bias=-4.5", "t=vertex:mip=lin:mip-bias=x", "t=vertex:wrap=mirror",
        "t=vertex:mip-lod=diagonal", "t=vertex:mip=lin:mip-lod=diag"}) {
    EXPECT_THROW(parse_gx_variant(bad), InputError) << bad;
  }
  for (const char* bad :
       {"", "t=pixel", "lut=1", "lut=1025", "t=vertex:t=vertex", "lobe=xf-spec:lut=64", "pow=exact",
        "t=vertex:lut=64x", "light-range=-1", "light-range=x", "light-range=1:light-range=2",
        "light-range=inf", "t=vertex:coverage=gpu", "coverage=console:coverage=dolphin"}) {
    EXPECT_THROW(parse_gx_variant(bad), InputError) << bad;
  }
}

TEST(GxVariantParse, TexgenAndXfNeedAnAffineT) {
  const Scene persp = load_scene(test::source_dir() / "scenes/backlit_sphere.json");
  const Scene ortho = load_scene(test::source_dir() / "scenes/ortho/backlit_sphere_ortho.json");
  EXPECT_NE(refusal(persp, parse_gx_variant("t=texgen")).find("perspective"), std::string::npos);
  EXPECT_NE(refusal(persp, parse_gx_variant("lobe=xf-spec")).find("perspective"),
            std::string::npos);
  EXPECT_EQ(refusal(ortho, parse_gx_variant("t=texgen")), "");
  EXPECT_EQ(refusal(persp, parse_gx_variant("t=vertex:lut=16")), "");
  const Scene point = load_scene(test::source_dir() / "scenes/three_point_blob.json");
  EXPECT_NE(refusal(point, parse_gx_variant("t=texgen")), "");
}

}  // namespace
}  // namespace lt::gx
