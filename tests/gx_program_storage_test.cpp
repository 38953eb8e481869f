// A user's own GX C declares how the scene's mesh is stored and sent, as a game does (issue 46
// step 4): GX_SetVtxAttrFmt on GX_VTXFMT0, GX_SetVtxDesc with GX_INDEX8/16 and GX_SetArray. The
// file is the generated program of the default (F32) variant, printed, with its declarations
// edited as a porter edits them; the expectation is the frame and FIFO log of the variant whose
// axes say the same storage (`vtx=s16/8:nrm=s8:clr=rgb565`, `:draw=indexed`), reached through the
// variant parser and the generated programs: an independent route to the same bytes.
// - the declared storage renders the variant's frame byte for byte, and not the F32 frame;
// - an indexed declaration writes the variant's :draw=indexed FIFO log byte for byte;
// - a bad declaration is one InputError naming the file and the declaration's line (a type the
//   attribute cannot have, a fraction the mesh overflows, direct and indexed mixed, GX_INDEX8
//   past its array, a stride that does not fit, passes or a variant axis that say otherwise).
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "gx/program/printer.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_path.h"
#include "paths/gx/scene_vertices.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

constexpr int kWidth = 96, kHeight = 72;
const char* const kStored = "t=vertex:vtx=s16/8:nrm=s8:clr=rgb565";

// A scene with a vertex colour (GX_VA_CLR0), so every declared attribute is sent.
const Scene& baked_blob() {
  static const Scene scene = load_scene(test::source_dir() / "scenes/baked_blob.json");
  return scene;
}

// The default variant's generated programs as C, what `ltrender export gx` writes.
const std::string& f32_program_text() {
  static const std::string text =
      print_program(generate_programs(baked_blob(), parse_gx_variant("t=vertex")).file);
  return text;
}

const std::vector<std::pair<std::string, std::string>> kS16S8Rgb565 = {
    {"GX_VA_POS, GX_POS_XYZ, GX_F32, 0", "GX_VA_POS, GX_POS_XYZ, GX_S16, 8"},
    {"GX_VA_NRM, GX_NRM_XYZ, GX_F32, 0", "GX_VA_NRM, GX_NRM_XYZ, GX_S8, 0"},
    {"GX_VA_CLR0, GX_CLR_RGBA, GX_RGBA8, 0", "GX_VA_CLR0, GX_CLR_RGB, GX_RGB565, 0"}};

TEST(GxProgramStorage, ADeclaredStorageRendersTheVariantsFrameByteForByte) {
  test::TempDir dir;
  const fs::path file = dir / "stored.c";
  test::write_file(file, test::with_edits(f32_program_text(), kS16S8Rgb565));
  PathOptions options;
  options.program_file = file.string();
  const Image declared = render_scene(baked_blob(), "gx", "t=vertex", kWidth, kHeight, options);
  const Image variant = render_scene(baked_blob(), "gx", kStored, kWidth, kHeight);
  const Image f32 = render_scene(baked_blob(), "gx", "t=vertex", kWidth, kHeight);
  ASSERT_EQ(declared.rgba.size(), variant.rgba.size());
  EXPECT_EQ(declared.rgba, variant.rgba);
  EXPECT_NE(declared.rgba, f32.rgba) << "the declaration changed nothing";
  // The same storage named both ways is one request, not a conflict.
  EXPECT_EQ(render_scene(baked_blob(), "gx", std::string(kStored), kWidth, kHeight, options).rgba,
            variant.rgba);
}

TEST(GxProgramStorage, AnIndexedDeclarationWritesTheVariantsIndexedFifoLog) {
  test::TempDir dir;
  const fs::path file = dir / "indexed.c";
  auto edits = kS16S8Rgb565;
  for (const char* a : {"GX_VA_POS", "GX_VA_NRM", "GX_VA_CLR0", "GX_VA_TEX0"})
    edits.push_back({std::string("GX_SetVtxDesc(") + a + ", GX_DIRECT);",
                     std::string("GX_SetVtxDesc(") + a + ", GX_INDEX16);"});
  // Packed arrays: 3 x s16, 3 x s8, one RGB565, one f32 t.
  edits.push_back({"GX_ClearVtxDesc();",
                   "GX_ClearVtxDesc();\n  GX_SetArray(GX_VA_POS, positions, 6);\n"
                   "  GX_SetArray(GX_VA_NRM, normals, 3);\n  GX_SetArray(GX_VA_CLR0, colours, 2);\n"
                   "  GX_SetArray(GX_VA_TEX0, t, 4);"});
  test::write_file(file, test::with_edits(f32_program_text(), edits));
  const PathInfo& gx = gx_path_info();
  const std::vector<std::uint8_t> declared =
      gx.fifo_log(baked_blob(), "t=vertex", PathOptions{file.string(), ""}, kWidth, kHeight);
  const std::vector<std::uint8_t> variant =
      gx.fifo_log(baked_blob(), std::string(kStored) + ":draw=indexed", {}, kWidth, kHeight);
  const std::vector<std::uint8_t> direct = gx.fifo_log(baked_blob(), kStored, {}, kWidth, kHeight);
  EXPECT_EQ(declared, variant);
  EXPECT_NE(declared, direct);
}

// A bad declaration: the edit, the text the refused line holds, and a part of the message.
struct BadDeclaration {
  const char* what;
  std::vector<std::pair<std::string, std::string>> edits;
  const char* line_holds;
  const char* message;
};

class GxBadStorageDeclaration : public ::testing::TestWithParam<BadDeclaration> {};

TEST_P(GxBadStorageDeclaration, IsRefusedNamingTheFileAndLine) {
  const BadDeclaration& c = GetParam();
  test::TempDir dir;
  const fs::path file = dir / "bad.c";
  const std::string text = test::with_edits(f32_program_text(), c.edits);
  test::write_file(file, text);
  try {
    (void)scene_programs_for(baked_blob(), parse_gx_variant("t=vertex"), file.string());
    FAIL() << c.what << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string()) << e.what();
    EXPECT_EQ(e.where().substr(0, e.where().find(':')),
              std::to_string(test::line_holding(text, c.line_holds)))
        << e.what();
    EXPECT_NE(e.what_only().find(c.message), std::string::npos) << e.what();
    EXPECT_EQ(test::count_lines(std::string(e.what()) + "\n"), 1);
  }
}

const BadDeclaration kBadDeclarations[] = {
    // baked_blob's positions reach 1.2: s8/7 holds -1 .. 0.99 (vertex_storage's own message).
    {"fraction_the_mesh_overflows",
     {{"GX_VA_POS, GX_POS_XYZ, GX_F32, 0", "GX_VA_POS, GX_POS_XYZ, GX_S8, 7"}},
     "GX_S8, 7",
     "s8/7 holds -1 .. 0.992188; the mesh's positions reach"},
    {"type_a_normal_cannot_have",
     {{"GX_VA_NRM, GX_NRM_XYZ, GX_F32, 0", "GX_VA_NRM, GX_NRM_XYZ, GX_U8, 0"}},
     "GX_U8",
     "'u8' is not a normal type"},
    {"normal_frac_other_than_its_exponent",
     {{"GX_VA_NRM, GX_NRM_XYZ, GX_F32, 0", "GX_VA_NRM, GX_NRM_XYZ, GX_S8, 8"}},
     "GX_S8, 8",
     "fixed by its type"},
    {"component_type_for_a_colour",
     {{"GX_VA_CLR0, GX_CLR_RGBA, GX_RGBA8, 0", "GX_VA_CLR0, GX_CLR_RGBA, GX_S16, 0"}},
     "GX_S16",
     "is a component type"},
    {"colour_encoding_for_a_position",
     {{"GX_VA_POS, GX_POS_XYZ, GX_F32, 0", "GX_VA_POS, GX_POS_XYZ, GX_RGB565, 0"}},
     "GX_RGB565",
     "is a colour encoding"},
    {"direct_and_indexed_in_one_vertex",
     {{"GX_SetVtxDesc(GX_VA_NRM, GX_DIRECT);", "GX_SetVtxDesc(GX_VA_NRM, GX_INDEX8);"}},
     "GX_INDEX8",
     "every attribute alike"},
    // baked_blob's positions are hundreds of distinct elements: GX_INDEX8 cannot reach them.
    {"index8_past_its_array",
     {{"GX_SetVtxDesc(GX_VA_POS, GX_DIRECT);", "GX_SetVtxDesc(GX_VA_POS, GX_INDEX8);"},
      {"GX_SetVtxDesc(GX_VA_NRM, GX_DIRECT);", "GX_SetVtxDesc(GX_VA_NRM, GX_INDEX8);"},
      {"GX_SetVtxDesc(GX_VA_CLR0, GX_DIRECT);", "GX_SetVtxDesc(GX_VA_CLR0, GX_INDEX8);"},
      {"GX_SetVtxDesc(GX_VA_TEX0, GX_DIRECT);", "GX_SetVtxDesc(GX_VA_TEX0, GX_INDEX8);"}},
     "GX_SetVtxDesc(GX_VA_POS, GX_INDEX8)",
     "GX_INDEX8 indexes at most 255 elements; GX_VA_POS's array holds"},
    {"a_stride_that_does_not_fit",
     {{"GX_ClearVtxDesc();", "GX_ClearVtxDesc();\n  GX_SetArray(GX_VA_POS, positions, 8);"}},
     "GX_SetArray",
     "GX_SetArray: stride 8 where GX_VA_POS stored as f32 takes 12"},
};

INSTANTIATE_TEST_SUITE_P(Cases, GxBadStorageDeclaration, ::testing::ValuesIn(kBadDeclarations),
                         [](const auto& info) { return std::string(info.param.what); });

TEST(GxProgramStorage, PassesDeclaringTheMeshOtherwiseAreRefusedAtTheSecond) {
  test::TempDir dir;
  const fs::path file = dir / "two.c";
  // Only the second pass's position: its line is the one named.
  std::string text = f32_program_text();
  const std::string from = "GX_VA_POS, GX_POS_XYZ, GX_F32, 0";
  const size_t second = text.find(from, text.find(from) + 1);
  ASSERT_NE(second, std::string::npos);
  text.replace(second, from.size(), "GX_VA_POS, GX_POS_XYZ, GX_S16, 8");
  test::write_file(file, text);
  try {
    (void)scene_programs_for(baked_blob(), parse_gx_variant("t=vertex"), file.string());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), file.string());
    EXPECT_EQ(e.where().substr(0, e.where().find(':')),
              std::to_string(test::line_holding(text, "GX_S16, 8")));
    EXPECT_NE(e.what_only().find("stored once a frame"), std::string::npos) << e.what();
  }
}

TEST(GxProgramStorage, AVariantAxisThatSaysOtherwiseIsRefusedNamingBoth) {
  test::TempDir dir;
  const fs::path file = dir / "stored.c";
  test::write_file(file, test::with_edits(f32_program_text(), kS16S8Rgb565));
  try {
    (void)scene_programs_for(baked_blob(), parse_gx_variant("t=vertex:vtx=s16/7"), file.string());
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "--variant");
    EXPECT_NE(e.what_only().find(":vtx=s16/7 where " + file.string()), std::string::npos)
        << e.what();
    EXPECT_NE(e.what_only().find("declares s16/8"), std::string::npos) << e.what();
  }
}

// `--format c` declares the variant's storage (issue 46 step 5): the generated program of a
// stored variant is the F32 program with the very declarations a porter writes by hand
// (kS16S8Rgb565 above, the edits the tests before read back), and the exported file, read back
// with `render --program`, draws the variant's frame; a user's edit of one declaration draws the
// frame of the variant that says the same.
TEST(GxExportDeclaresStorage, AsThePorterWritesItByHand) {
  EXPECT_EQ(print_program(generate_programs(baked_blob(), parse_gx_variant(kStored)).file),
            test::with_edits(f32_program_text(), kS16S8Rgb565));
}

// The exported file (`ltrender export gx`, comment block and all) under --program.
fs::path exported_c(const test::TempDir& dir, const std::string& variant) {
  const fs::path file = dir / "export.c";
  const test::RunResult r =
      test::run_ltrender("export gx " + (test::source_dir() / "scenes/baked_blob.json").string() +
                         " --variant " + variant + " -o " + file.string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return file;
}

TEST(GxExportDeclaresStorage, TheExportedFileRendersTheVariantsFrameAndAnEditedOneItsVariants) {
  test::TempDir dir;
  const fs::path file = exported_c(dir, kStored);
  PathOptions options;
  options.program_file = file.string();
  const Image read_back = render_scene(baked_blob(), "gx", "t=vertex", kWidth, kHeight, options);
  const Image s16_8 = render_scene(baked_blob(), "gx", kStored, kWidth, kHeight);
  EXPECT_EQ(read_back.rgba, s16_8.rgba);
  // The porter moves the positions to 10 fractional bits.
  test::write_file(file, test::with_edits(test::read_file(file), {{"GX_S16, 8", "GX_S16, 10"}}));
  const Image edited = render_scene(baked_blob(), "gx", "t=vertex", kWidth, kHeight, options);
  const Image s16_10 =
      render_scene(baked_blob(), "gx", "t=vertex:vtx=s16/10:nrm=s8:clr=rgb565", kWidth, kHeight);
  EXPECT_EQ(edited.rgba, s16_10.rgba);
  EXPECT_NE(edited.rgba, s16_8.rgba) << "the edit changed nothing";
}

// An indexed display list with /auto fractions: the file declares each array's index and one
// fraction an attribute. baked_blob is one object, so its positions' /auto is the variant's; its
// two lights' t may each take their own under uv=s16/auto, and the file declares the smallest,
// the widest fraction (vertex_quantiser.h widest_fraction) that holds every light's t. Read
// back, its FIFO log (the draw taken from :draw=list) is the log of the variant that says that
// fraction, to the byte.
TEST(GxExportDeclaresStorage, AnIndexedListWithAutoFractionsWritesTheVariantsFifoLog) {
  test::TempDir dir;
  const std::string storage = "t=vertex:vtx=s16:nrm=s16:clr=rgba4";
  const fs::path file = exported_c(dir, storage + ":uv=s16:draw=list");
  EXPECT_NE(test::read_file(file).find("GX_SetVtxDesc(GX_VA_POS, GX_INDEX16);"), std::string::npos)
      << "the blob has more than 255 positions";
  const SceneView view = SceneView::of(baked_blob());
  const VertexStream stream = make_vertex_stream(baked_blob(), baked_blob().objects[0], view);
  int t_frac = kMaxFracBits;
  for (const std::vector<float>& t : stream.t_per_light) {
    const auto [lo, hi] = std::minmax_element(t.begin(), t.end());
    t_frac = std::min(t_frac, widest_fraction(*lo, *hi, ComponentType::S16).value());
  }
  const PathInfo& gx = gx_path_info();
  EXPECT_EQ(gx.fifo_log(baked_blob(), "t=vertex:draw=list", PathOptions{file.string(), ""}, kWidth,
                        kHeight),
            gx.fifo_log(baked_blob(), storage + ":uv=s16/" + std::to_string(t_frac) + ":draw=list",
                        {}, kWidth, kHeight));
}

}  // namespace
}  // namespace lt::gx
