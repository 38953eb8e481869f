// `render --program` reads users' TPL files as libogc does (program/calls_tpl.cpp, issue 47): the
// `--format c` program of a variant, edited to take its textures from a TPL (opened from a file
// beside it or from an array in it, each texture with TPL_GetTexture / TPL_GetTextureCI), draws
// the variant's own frame, byte for byte; a missing, truncated or corrupt TPL, or an id past its
// table, is refused in one line naming the file and the offset or id.
#include <gtest/gtest.h>

#include <algorithm>

#include "core/error.h"
#include "gx/program/interpreter.h"
#include "gx/program/parser.h"
#include "gx/program/printer.h"
#include "gx/tpl_file.h"
#include "gx_program_util.h"
#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/module/module_textures.h"
#include "render/session.h"
#include "test_util.h"

namespace lt::gx {
namespace {

constexpr int kSize = 64;

// The variant's `--format c` program with every texture taken from the TPL of its textures:
// from `tpl_file` (relative to the program) when given, else from the array in the program.
struct TplProgram {
  std::string text;
  std::vector<u8> tpl;
};
TplProgram tpl_program(const Scene& scene, const std::string& variant,
                       const std::string& tpl_file) {
  const ScenePlan plan = plan_scene(scene, parse_gx_variant(variant));
  ProgramFile file = emit_programs(plan).file;
  const ModuleTextures textures = module_textures(plan);
  file.top_level = with_textures_in_tpl(file.top_level, textures);
  const std::vector<u8> tpl = write_tpl(textures.textures);
  if (tpl_file.empty()) {
    file.top_level.push_back(Statement::of(Call(
        "TPL_OpenTPLFromMemory", {Arg::address_of(kModuleTplFile), Arg::identifier(kModuleTplArray),
                                  Arg::literal(static_cast<long long>(tpl.size()))})));
  } else {
    std::erase_if(file.top_level, [](const Statement& s) {
      return s.kind == Statement::Kind::Declaration && s.declaration.name == kModuleTplArray;
    });
    file.top_level.push_back(Statement::of(
        Call("TPL_OpenTPLFromFile", {Arg::address_of(kModuleTplFile), Arg::string(tpl_file)})));
  }
  for (Function& f : file.functions) f = take_textures_from_tpl(f, textures);
  return {print_program(file), tpl};
}

// From a file in a folder beside the program (read relative to the program, not the working
// directory) and from an array: both are the variant's frame, for a CI4 map (IA8 palette,
// TPL_GetTextureCI) and a CMPR one. One suite of plain tests: one process start, not two.
TEST(GxTplProgram, DrawsTheVariantsFrameFromAFileAndFromMemory) {
  for (const auto& [scene_file, variant] :
       {std::pair<std::string, std::string>{"scenes/maps/sphere_map.json", "t=vertex:map=ci4"},
        {"scenes/maps/sphere_rgb_ramp.json", "t=vertex:map=cmpr"},
        // A mip chain: TPL_GetTexture gives the object the header's levels and LOD fields
        // [OGC tpl.c L241-248], the program's GX_InitTexObjLOD after it its own.
        {"scenes/maps/sphere_map.json", "t=vertex:mip=lin:mip-bias=2"}}) {
    SCOPED_TRACE(scene_file + " --variant " + variant);
    const Scene scene = load_scene(test::source_dir() / scene_file);
    const Image direct = render_scene(scene, "gx", variant, kSize, kSize);
    test::TempDir dir;
    fs::create_directory(dir / "maps");
    const TplProgram from_file = tpl_program(scene, variant, "maps/textures.tpl");
    ASSERT_NE(from_file.text.find("TPL_OpenTPLFromFile(&ltrender_tpl, \"maps/textures.tpl\")"),
              std::string::npos);
    test::write_file(dir / "maps/textures.tpl",
                     std::string(from_file.tpl.begin(), from_file.tpl.end()));
    test::write_file(dir / "file.c", from_file.text);
    const Image by_file = render_scene(scene, "gx", variant, kSize, kSize,
                                       PathOptions{(dir / "file.c").string(), ""});
    EXPECT_TRUE(by_file.rgba == direct.rgba) << "the frame drawn from maps/textures.tpl differs";
    test::write_file(dir / "memory.c", tpl_program(scene, variant, "").text);
    const Image by_memory = render_scene(scene, "gx", variant, kSize, kSize,
                                         PathOptions{(dir / "memory.c").string(), ""});
    EXPECT_TRUE(by_memory.rgba == direct.rgba) << "the frame drawn from the TPL array differs";
    if (variant.find(":mip=") != std::string::npos) {
      const Image level0 = render_scene(scene, "gx", "t=vertex", kSize, kSize);
      EXPECT_FALSE(level0.rgba == direct.rgba) << "the chain changes no pixel: nothing is held";
    }
  }
}

// `ltrender render --program` with a TPL cut short: exit 2, one line naming the TPL and the
// offset, and no image written (the command's side of GxBadTpl's refusals).
TEST(GxTplProgram, ATruncatedTplExitsTwoWithOneLineAndWritesNothing) {
  const std::string scene_file = (test::source_dir() / "scenes/maps/sphere_map.json").string();
  const Scene scene = load_scene(scene_file);
  test::TempDir dir;
  TplProgram p = tpl_program(scene, "t=vertex:map=ci4", "maps.tpl");
  p.tpl.resize(p.tpl.size() - 40);  // into the last block
  test::write_file(dir / "maps.tpl", std::string(p.tpl.begin(), p.tpl.end()));
  test::write_file(dir / "bad.c", p.text);
  const fs::path out = dir / "out.png";
  const test::RunResult r =
      test::run_ltrender("render " + scene_file +
                         " --path gx --variant t=vertex:map=ci4 --width 32 --height 32 "
                         "--program " +
                         (dir / "bad.c").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(test::count_lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find((dir / "maps.tpl").string() + ":offset "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("past the end"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

// What TPL_GetTexture gives the texture object, from an array in the program: the header's
// format, size, wraps and texels, linear filters (mipmap off); and a later GX_InitTexObjWrapMode
// and GX_InitTexObjFilterMode change the object as they change a game's.
TEST(GxTplProgram, TheObjectTakesTheHeaderAndTheProgramsLaterCallsWin) {
  TplTexture t;
  t.format = TexFormat::IA8;
  t.width = 8;
  t.height = 4;
  t.wrap_s = 1;                                                               // GX_REPEAT
  t.wrap_t = 2;                                                               // GX_MIRROR
  for (int k = 0; k < 64; ++k) t.data.push_back(static_cast<u8>(3 * k + 1));  // two 4x4 tiles
  const std::vector<u8> tpl = write_tpl({t});
  std::string array = test::c_byte_array("maps_tpl", tpl);
  array += "TPLFile tpl;\nGXTexObj tex;\nTPL_OpenTPLFromMemory(&tpl, maps_tpl, " +
           std::to_string(tpl.size()) + ");\nTPL_GetTexture(&tpl, 0, &tex);\n";
  auto loaded = [&](const std::string& then) {
    const ProgramFile f = parse_program(array + then + "GX_LoadTexObj(&tex, GX_TEXMAP2);\n", "p.c");
    const GxState state = run_program("p.c", {&f.top_level});
    EXPECT_TRUE(state.textures[2].has_value());
    return state.textures[2].value_or(TextureObject{});
  };
  const TextureObject as_read = loaded("");
  EXPECT_EQ(as_read.format, 3);  // GX_TF_IA8
  EXPECT_EQ(as_read.width, 8);
  EXPECT_EQ(as_read.height, 4);
  EXPECT_EQ(as_read.wrap_s, 1);
  EXPECT_EQ(as_read.wrap_t, 2);
  EXPECT_TRUE(as_read.linear);
  EXPECT_EQ(as_read.data, t.data);
  const TextureObject changed = loaded(
      "GX_InitTexObjWrapMode(&tex, GX_CLAMP, GX_CLAMP);\n"
      "GX_InitTexObjFilterMode(&tex, GX_NEAR, GX_NEAR);\n");
  EXPECT_EQ(changed.wrap_s, 0);
  EXPECT_EQ(changed.wrap_t, 0);
  EXPECT_FALSE(changed.linear);
  EXPECT_EQ(changed.data, t.data);
}

// A bad TPL or TPL call: how the file or the program is spoiled, and what the one line says.
struct BadTpl {
  const char* what;
  void (*spoil)(std::vector<u8>& tpl, std::string& program);
  const char* file;   // the file the line names
  const char* where;  // InputError::where(): the offset in the TPL; for the program, a call its
                      // line holds
  const char* message;
};

void replace_in_program(std::string& text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
}
// Big-endian u32 at `at`, as the TPL holds it.
void put_tpl_u32(std::vector<u8>& b, size_t at, u32 v) {
  for (size_t k = 0; k < 4; ++k) b[at + k] = static_cast<u8>(v >> (24 - 8 * k));
}
u32 tpl_u32_at(const std::vector<u8>& b, size_t at) {
  return u32{b[at]} << 24 | u32{b[at + 1]} << 16 | u32{b[at + 2]} << 8 | b[at + 3];
}
// The image header of texture 1 (the map; texture 0 is the LUT), from the descriptor table.
size_t map_header(const std::vector<u8>& b) {
  return tpl_u32_at(b, 12 + 8);
}

class GxBadTpl : public ::testing::TestWithParam<BadTpl> {};

TEST_P(GxBadTpl, IsRefusedInOneLineNamingTheFileAndTheOffsetOrId) {
  const BadTpl& c = GetParam();
  const Scene scene = load_scene(test::source_dir() / "scenes/maps/sphere_map.json");
  test::TempDir dir;
  TplProgram p = tpl_program(scene, "t=vertex:map=ci4", "maps.tpl");
  c.spoil(p.tpl, p.text);
  test::write_file(dir / "maps.tpl", std::string(p.tpl.begin(), p.tpl.end()));
  test::write_file(dir / "bad.c", p.text);
  try {
    (void)render_scene(scene, "gx", "t=vertex:map=ci4", kSize, kSize,
                       PathOptions{(dir / "bad.c").string(), ""});
    FAIL() << c.what << ": accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (dir / c.file).string()) << e.what();
    if (std::string(c.file) == "bad.c") {
      const int line = std::stoi(e.where());
      std::string text = p.text;
      for (int k = 1; k < line; ++k) text.erase(0, text.find('\n') + 1);
      EXPECT_NE(text.substr(0, text.find('\n')).find(c.where), std::string::npos) << e.what();
    } else {
      EXPECT_EQ(e.where(), c.where) << e.what();
    }
    EXPECT_NE(e.what_only().find(c.message), std::string::npos) << e.what();
    EXPECT_EQ(test::count_lines(std::string(e.what()) + "\n"), 1);
  }
}

const BadTpl kBadTpls[] = {
    {"missing_file",
     [](std::vector<u8>&, std::string& program) {
       replace_in_program(program, "\"maps.tpl\"", "\"absent.tpl\"");
     },
     "absent.tpl", "", ""},
    {"bad_magic", [](std::vector<u8>& tpl, std::string&) { tpl[0] ^= 0xff; }, "maps.tpl",
     "offset 0", "not a TPL file"},
    {"truncated_in_the_descriptors", [](std::vector<u8>& tpl, std::string&) { tpl.resize(16); },
     "maps.tpl", "offset 12", "truncated TPL"},
    {"texel_offset_past_the_end",
     [](std::vector<u8>& tpl, std::string&) { put_tpl_u32(tpl, map_header(tpl) + 8, 0x7fffff00); },
     "maps.tpl", "offset 2147483392", "runs past the end of the file"},
    {"width_no_format_takes",
     [](std::vector<u8>& tpl, std::string&) {
       tpl[map_header(tpl) + 2] = 0x08;  // the high byte: width 2048 + 64
     },
     "maps.tpl", "offset 64", "is outside 1..1024 per side"},
    {"unknown_format",
     [](std::vector<u8>& tpl, std::string&) { put_tpl_u32(tpl, map_header(tpl) + 4, 7); },
     "maps.tpl", "offset 68", "unknown texture format 7"},
    {"id_past_the_table",
     [](std::vector<u8>&, std::string& program) {
       replace_in_program(program, "TPL_GetTextureCI(&ltrender_tpl, 1,",
                          "TPL_GetTextureCI(&ltrender_tpl, 2,");
     },
     "bad.c", "TPL_GetTextureCI", "texture id 2 is past the 2 textures of"},
    {"unterminated_file_name",
     [](std::vector<u8>&, std::string& program) {
       replace_in_program(program, "\"maps.tpl\");", "\"maps.tpl);");
     },
     "bad.c", "TPL_OpenTPLFromFile(", "unterminated string"},
    {"tpl_never_opened",
     [](std::vector<u8>&, std::string& program) {
       replace_in_program(program, "TPL_OpenTPLFromFile(&ltrender_tpl, \"maps.tpl\");", "");
     },
     "bad.c", "TPL_GetTexture(", "ltrender_tpl was never opened"},
    {"colour_indexed_without_its_palette_call",
     [](std::vector<u8>&, std::string& program) {
       replace_in_program(
           program, "TPL_GetTextureCI(&ltrender_tpl, 1, &thickness, &thickness_tlut, GX_TLUT0)",
           "TPL_GetTexture(&ltrender_tpl, 1, &thickness)");
     },
     "bad.c", "TPL_GetTexture(", "a colour-indexed texture needs TPL_GetTextureCI"},
};

INSTANTIATE_TEST_SUITE_P(Cases, GxBadTpl, ::testing::ValuesIn(kBadTpls),
                         [](const auto& info) { return std::string(info.param.what); });

}  // namespace
}  // namespace lt::gx
