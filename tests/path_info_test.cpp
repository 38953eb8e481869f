// Every path's PathInfo the same way (issue 24): a typed variant parsed once, the registry's
// one message for an unknown listed name, and the evaluate step regress shares (render/evaluate.h).
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "core/error.h"
#include "paths/combiners/combiner_budget.h"
#include "paths/combiners/combiners_path.h"
#include "paths/path.h"
#include "render/evaluate.h"
#include "test_util.h"

namespace lt {
namespace {

std::string input_error(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Every listed name is its own canonical spelling, on every path (a grammar path may accept
// more spellings, never rename a listed one).
TEST(PathInfo, EveryListedVariantResolvesToItself) {
  for (const PathInfo& p : all_paths()) {
    EXPECT_EQ(resolve_variant(p, ""), p.variants.front().name) << p.name;
    for (const VariantInfo& v : p.variants) EXPECT_EQ(resolve_variant(p, v.name), v.name) << p.name;
  }
}

// The message a listed path gives for a name it does not have, written out here (not taken from
// the code that builds it): the path, and every valid name in the listed order.
TEST(PathInfo, AnUnknownListedVariantIsNamedWithTheValidOnes) {
  const std::string half = input_error([] { (void)resolve_variant(find_path("half"), "pow=sq"); });
  EXPECT_NE(half.find("path half has no such variant (valid: pow=exact, pow=sg, pow=unguarded)"),
            std::string::npos)
      << half;
  const std::string glsl = input_error([] { (void)resolve_variant(find_path("glsl"), "f32"); });
  EXPECT_NE(glsl.find("path glsl has no such variant (valid: pow=exact, pow=exact:f32)"),
            std::string::npos)
      << glsl;
  for (const char* name : {"reference", "flat"}) {
    const std::string e = input_error([&] { (void)resolve_variant(find_path(name), "x"); });
    EXPECT_NE(e.find(std::string("path ") + name + " has no such variant"), std::string::npos) << e;
  }
}

// The combiners variant is parsed once into its enum; the budget, which is given the user's
// text, parses it the same way (it used to count an unknown name as t=vertex).
TEST(PathInfo, CombinersVariantsAreTyped) {
  EXPECT_EQ(parse_combiners_variant(""), CombinersVariant::TVertex);
  EXPECT_EQ(parse_combiners_variant("t=vertex"), CombinersVariant::TVertex);
  EXPECT_EQ(parse_combiners_variant("t=texgen"), CombinersVariant::TTexgen);
  EXPECT_EQ(parse_combiners_variant("lobe=cube"), CombinersVariant::LobeCube);
  const std::string e = input_error([] { (void)parse_combiners_variant("lobe=cubes"); });
  EXPECT_NE(e.find("path combiners has no such variant (valid: t=vertex, t=texgen, lobe=cube)"),
            std::string::npos)
      << e;
  EXPECT_EQ(resolve_variant(find_path("combiners"), "lobe=cube"), "lobe=cube");
  Scene scene;
  const std::string b = input_error([&] { (void)combiner_budget(scene, "", "t=vertx"); });
  EXPECT_NE(b.find("path combiners has no such variant"), std::string::npos) << b;
}

// A path without a capability says so through its data, and calling it anyway is a bug
// (an internal-error abort), not a silent empty answer.
TEST(PathInfo, CapabilitiesFollowTheirData) {
  const PathInfo& half = find_path("half");
  EXPECT_TRUE(half.budget_profiles.empty());
  EXPECT_FALSE(half.writes_fifo_log);
  EXPECT_DEATH((void)half.budget(Scene{}, "", ""), "path half has no budget");
  EXPECT_TRUE(find_path("gx").writes_fifo_log);
  EXPECT_FALSE(find_path("combiners").budget_profiles.empty());
}

// `export TARGET`: TARGET is a path that exports (export_formats). A path that exports nothing,
// or no path, is refused in one line naming the valid targets, exit 2, nothing written.
TEST(PathInfo, ExportRefusesAPathThatExportsNothingNamingThoseThatDo) {
  std::string valid;
  for (const PathInfo& p : all_paths())
    if (!p.export_formats.empty()) valid += (valid.empty() ? "" : ", ") + p.name;
  EXPECT_NE(valid.find("gx"), std::string::npos) << valid;
  ASSERT_TRUE(find_path("glsl").export_formats.empty());
  test::TempDir dir;
  const std::string scene = (test::source_dir() / "scenes/backlit_sphere.json").string();
  const auto glsl = test::run_ltrender("export glsl " + scene + " -o " + (dir / "x.c").string());
  EXPECT_EQ(glsl.exit_code, 2);
  EXPECT_EQ(glsl.err,
            "ltrender: error: export:glsl: path glsl exports nothing (valid: " + valid + ")\n");
  const auto none = test::run_ltrender("export nope " + scene + " -o " + (dir / "x.c").string());
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err,
            "ltrender: error: export:nope: unknown export target (valid: " + valid + ")\n");
  EXPECT_FALSE(fs::exists(dir / "x.c"));
}

// `export --help` lists what the registry declares: every exporting path with its target, and
// every format with its summary and the extension it writes; gx's are the three of cli.md.
TEST(PathInfo, ExportHelpListsTheRegistrysFormats) {
  const auto help = test::run_ltrender("export --help");
  ASSERT_EQ(help.exit_code, 0) << help.err;
  for (const PathInfo& p : all_paths()) {
    if (p.export_formats.empty()) continue;
    EXPECT_NE(help.out.find(p.name + " (" + p.export_target + ")"), std::string::npos) << p.name;
    for (const ExportFormat& f : p.export_formats) {
      EXPECT_NE(help.out.find(f.name + ": " + f.summary), std::string::npos) << f.name;
      EXPECT_NE(help.out.find("FILE" + f.extension), std::string::npos) << f.name;
    }
  }
  std::vector<std::string> gx;
  for (const ExportFormat& f : find_path("gx").export_formats) gx.push_back(f.name);
  EXPECT_EQ(gx, (std::vector<std::string>{"c", "module", "dff"}));
}

// A path whose formats take none of --program, --frames, --width/--height, --light-range
// refuses each by name (PathInfo::export_variant's default) and exports the variant alone.
TEST(PathInfo, AnExportOptionThePathDoesNotTakeIsRefused) {
  struct TextExport : PathInfo {
    TextExport() {
      name = "text";
      variants = {{"plain", "one variant"}};
      export_formats = {{"txt", ".txt", "the scene as text"}};
    }
    std::unique_ptr<Path> create(const PathContext&, const std::string&) const override {
      return nullptr;
    }
  } text;
  EXPECT_EQ(text.export_variant(ExportRequest{}), "plain");
  const auto refused = [&](ExportRequest r) {
    return input_error([&] { (void)text.export_variant(r); });
  };
  EXPECT_NE(refused({.light_range = "5"}).find("--light-range"), std::string::npos);
  EXPECT_NE(refused({.frames = 3}).find("--frames"), std::string::npos);
  EXPECT_NE(refused({.height = 240}).find("--width/--height"), std::string::npos);
  const std::string program = refused({.program_file = "p.c"});
  EXPECT_NE(program.find("--program"), std::string::npos) << program;
  EXPECT_NE(program.find("path text"), std::string::npos) << program;
}

// regress's comparison with a golden: the golden's alpha is replaced by the render's coverage,
// both sides are compared as bytes. A golden that differs only where the render covers nothing
// has no covered error; one byte off inside the coverage is one LSB.
TEST(Evaluate, AGoldenIsComparedOverTheRendersCoverage) {
  // Values k/255 on both sides: the bytes k, whatever the rounding of a value between two bytes.
  const float k128 = 128.0f / 255.0f;
  Image render(2, 1), golden(2, 1);
  for (size_t i = 0; i < 2; ++i) {
    for (int c = 0; c < 3; ++c) render.rgba[i * 4 + c] = golden.rgba[i * 4 + c] = k128;
    golden.rgba[i * 4 + 3] = 1;  // a PNG's alpha: opaque
  }
  render.rgba[3] = 1;      // pixel 0 covered
  render.rgba[4 + 3] = 0;  // pixel 1 not
  golden.rgba[4] = 1.0f;   // 255 against 128, outside the coverage
  const Comparison far = compare_with_golden(render, golden);
  EXPECT_EQ(far.covered.max_lsb, 0.0);
  EXPECT_DOUBLE_EQ(far.image.max_lsb, 127.0);
  golden.rgba[4] = k128;
  golden.rgba[0] = 129.0f / 255.0f;  // one byte off inside the coverage
  EXPECT_DOUBLE_EQ(compare_with_golden(render, golden).covered.max_lsb, 1.0);
}

}  // namespace
}  // namespace lt
