// Every `export gx` compiles for the console (issue 25): each demo, ortho and map scene, each gx
// variant that renders it, through Debian's PowerPC cross compiler against libogc's headers with
// `-std=gnu11 -Wall -Wextra -Werror`. libogc is not a Debian package, so the test needs a checkout
// of it: LTRENDER_LIBOGC=/path/to/libogc[:/another/libogc] (each holding gc/gccore.h), e.g. the
// current headers and those before the 2025 rework, which moved ATTRIBUTE_ALIGN from gctypes.h to
// gcutil.h. Without it the test skips and says how to turn it on (docs: porting to the Wii).
// The same holds for every module (`--format module`) and for the Wii sample examples/wii/main.c.
#include <gtest/gtest.h>

#include <sstream>

#include "load/load_scene.h"
#include "paths/path.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt {
namespace {

std::vector<fs::path> libogc_checkouts() {
  std::vector<fs::path> out;
  const char* env = std::getenv("LTRENDER_LIBOGC");
  if (!env) return out;
  std::istringstream parts(env);
  for (std::string p; std::getline(parts, p, ':');) {
    if (!p.empty()) out.emplace_back(p);
  }
  return out;
}

// devkitPPC's Wii rules compile with -DGEKKO and -mrvl, whose spec defines HW_RVL; Debian's
// powerpc-linux-gnu-gcc has no -mrvl, so both are given here. -c only: nothing is linked.
std::string compile_command(const fs::path& source, const fs::path& libogc, const fs::path& log) {
  return "powerpc-linux-gnu-gcc -std=gnu11 -Wall -Wextra -Werror -DGEKKO -DHW_RVL -I" +
         (libogc / "gc").string() + " -c " + source.string() + " -o " + source.string() + ".o >" +
         log.string() + " 2>&1";
}

std::vector<std::string> export_scenes() {
  std::vector<std::string> out;
  for (const char* folder : {"scenes", "scenes/ortho", "scenes/maps"}) {
    for (const std::string& s : test::json_files(folder)) out.push_back(s);
  }
  return out;
}

class GxExportCompiles : public ::testing::TestWithParam<std::string> {};

// Exports `scene` in each variant `wanted` accepts (and the scene renders) with `format_args`,
// compiles each file against every checkout, and returns how many compiled.
int expect_exports_compile(const std::string& scene_param, const std::string& format_args,
                           bool (*wanted)(const std::string& variant)) {
  const std::vector<fs::path> checkouts = libogc_checkouts();
  EXPECT_EQ(std::system("command -v powerpc-linux-gnu-gcc >/dev/null"), 0)
      << "powerpc-linux-gnu-gcc is missing (scripts/setup.sh installs gcc-powerpc-linux-gnu)";
  for (const fs::path& ogc : checkouts)
    EXPECT_TRUE(fs::exists(ogc / "gc" / "gccore.h")) << ogc << " holds no gc/gccore.h";
  const fs::path scene_file = test::source_dir() / scene_param;
  const Scene scene = load_scene(scene_file);
  const PathInfo& gx = find_path("gx");
  test::TempDir dir;
  int compiled = 0;
  for (const VariantInfo& v : gx.variants) {
    if (!gx.refusal(scene, v.name).empty() || !wanted(v.name)) continue;
    const fs::path c = dir / (test::test_param_name(v.name) + ".c");
    auto export_c = [&](const std::string& variant) {
      return test::run_ltrender("export gx " + scene_file.string() + " --variant " + variant +
                                format_args + " -o " + c.string());
    };
    test::RunResult r = export_c(v.name);
    // A 1024x1024 RGBA8 thickness map makes a C file over the program input cap (the teapot of
    // scenes/maps): export refuses it and names :map=rgb565, which halves the array.
    if (r.exit_code == 2 && r.err.find("program file may be") != std::string::npos)
      r = export_c(v.name + ":map=rgb565");
    EXPECT_EQ(r.exit_code, 0) << v.name << ": " << r.err;
    if (r.exit_code != 0) continue;
    for (const fs::path& ogc : checkouts) {
      const fs::path log = dir / "cc.log";
      const int status = std::system(compile_command(c, ogc, log).c_str());
      EXPECT_EQ(status, 0) << scene_param << " --variant " << v.name << format_args << " against "
                           << ogc << ":\n"
                           << test::read_file(log);
      ++compiled;
    }
  }
  return compiled;
}

TEST_P(GxExportCompiles, WithThePowerPcCompilerAgainstLibogc) {
  if (libogc_checkouts().empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout (or several, ':'-separated) to "
                    "compile every export for the console";
  EXPECT_GT(expect_exports_compile(GetParam(), "", [](const std::string&) { return true; }), 0)
      << "no gx variant renders " << GetParam();
}

// The module (`--format module`) of t=vertex, t=texgen, t=texgen:view=object, lobe=xf-spec and
// lobe=xf-spec:view=object, where the scene takes them (the other variants change a LUT's size or
// the emulator's rounding, not the module's code), and the Wii sample examples/wii/main.c with the
// module of the scene its comment names.
TEST_P(GxExportCompiles, AsAModuleWithThePowerPcCompilerAgainstLibogc) {
  if (libogc_checkouts().empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout (or several, ':'-separated) to "
                    "compile every module for the console";
  EXPECT_GT(expect_exports_compile(GetParam(), " --format module",
                                   [](const std::string& v) {
                                     return v == "t=vertex" || v == "t=texgen" ||
                                            v == "t=texgen:view=object" || v == "lobe=xf-spec" ||
                                            v == "lobe=xf-spec:view=object";
                                   }),
            0)
      << "no gx variant of " << GetParam() << " has a module";
}

TEST(GxWiiExample, CompilesWithTheModuleItNames) {
  const std::vector<fs::path> checkouts = libogc_checkouts();
  if (checkouts.empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout to compile examples/wii/main.c";
  test::TempDir dir;
  const test::RunResult r = test::run_ltrender(
      "export gx " + (test::source_dir() / "scenes/backlit_sphere.json").string() +
      " --format module -o " + (dir / "ltrender_module.c").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path main_c = dir / "main.c";
  fs::copy_file(test::source_dir() / "examples/wii/main.c", main_c);
  for (const fs::path& ogc : checkouts) {
    const fs::path log = dir / "cc.log";
    EXPECT_EQ(std::system(compile_command(main_c, ogc, log).c_str()), 0)
        << "examples/wii/main.c against " << ogc << ":\n"
        << test::read_file(log);
  }
}

// A module with a declared light range (`--light-range`): the setup without the scan.
TEST(GxModuleLightRange, CompilesWithThePowerPcCompilerAgainstLibogc) {
  const std::vector<fs::path> checkouts = libogc_checkouts();
  if (checkouts.empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout to compile a --light-range module";
  test::TempDir dir;
  for (const char* variant : {"t=vertex", "t=texgen:view=object", "lobe=xf-spec:view=object"}) {
    const fs::path c = dir / "module.c";
    const test::RunResult r = test::run_ltrender(
        "export gx " + (test::source_dir() / "scenes/three_point_blob.json").string() +
        " --variant " + variant + " --light-range 0.5 --format module -o " + c.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(test::read_file(c).find("#define LTRENDER_LIGHT_RANGE 0.5"), std::string::npos);
    for (const fs::path& ogc : checkouts) {
      const fs::path log = dir / "cc.log";
      EXPECT_EQ(std::system(compile_command(c, ogc, log).c_str()), 0)
          << variant << " against " << ogc << ":\n"
          << test::read_file(log);
    }
  }
}

// Modules whose maps are colour-indexed (TPL_GetTextureCI) or CMPR: the TPL calls and the
// TPLFile of libogc's tpl.h, which both eras declare alike (unchanged since 2011).
TEST(GxModuleTplCompiles, WithThePowerPcCompilerAgainstLibogc) {
  const std::vector<fs::path> checkouts = libogc_checkouts();
  if (checkouts.empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout to compile a module's TPL calls";
  test::TempDir dir;
  for (const char* scene_variant : {"sphere_map.json --variant t=vertex:map=ci4",
                                    "sphere_rgb_ramp.json --variant t=vertex:map=cmpr"}) {
    const fs::path c = dir / "module.c";
    const test::RunResult r =
        test::run_ltrender("export gx " + (test::source_dir() / "scenes/maps").string() + "/" +
                           scene_variant + " --format module -o " + c.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(test::read_file(c).find("TPL_OpenTPLFromMemory"), std::string::npos);
    for (const fs::path& ogc : checkouts) {
      const fs::path log = dir / "cc.log";
      EXPECT_EQ(std::system(compile_command(c, ogc, log).c_str()), 0)
          << scene_variant << " against " << ogc << ":\n"
          << test::read_file(log);
    }
  }
}

// `--format c` of a stored, indexed display-list variant: its declarations (GX_S16 with a
// fraction, GX_S8 normals, GX_RGB565, GX_INDEX8/GX_INDEX16) are libogc's names and arguments.
TEST(GxExportStoredDeclarations, CompileWithThePowerPcCompilerAgainstLibogc) {
  const std::vector<fs::path> checkouts = libogc_checkouts();
  if (checkouts.empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout to compile a stored variant's C";
  test::TempDir dir;
  const fs::path c = dir / "stored.c";
  const test::RunResult r = test::run_ltrender(
      "export gx " + (test::source_dir() / "scenes/baked_blob.json").string() +
      " --variant t=vertex:vtx=s16:nrm=s8:clr=rgb565:uv=s16:draw=list -o " + c.string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string text = test::read_file(c);
  EXPECT_NE(text.find("GX_RGB565"), std::string::npos);
  EXPECT_NE(text.find("GX_INDEX8"), std::string::npos) << "the blob's colour array";
  EXPECT_NE(text.find("GX_INDEX16"), std::string::npos) << "the blob's positions";
  for (const fs::path& ogc : checkouts) {
    const fs::path log = dir / "cc.log";
    EXPECT_EQ(std::system(compile_command(c, ogc, log).c_str()), 0) << "against " << ogc << ":\n"
                                                                    << test::read_file(log);
  }
}

// The module of a stored variant (module_stored.h): its arrays (ATTRIBUTE_ALIGN(32)), its
// display lists and indexed draws (GX_SetArray, GX_BeginDispList, GX_Position1x16, ...) are
// libogc's calls, as a list with the per-vertex t the CPU rewrites every frame (t=vertex, its
// fraction chosen per frame: ltr_stored_write_t), and as strips, one scene with a map's UVs.
TEST(GxModuleStoredCompiles, WithThePowerPcCompilerAgainstLibogc) {
  const std::vector<fs::path> checkouts = libogc_checkouts();
  if (checkouts.empty())
    GTEST_SKIP() << "set LTRENDER_LIBOGC to a libogc checkout to compile a stored module";
  test::TempDir dir;
  struct Case {
    const char *scene, *variant, *declares;  // `declares`: a call the variant's storage needs
  };
  const Case cases[] = {
      {"scenes/three_point_blob.json",
       "t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list", "ltr_stored_write_t("},
      {"scenes/albedo_checker.json",
       "lobe=xf-spec:view=object:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=strips",
       "GX_TRIANGLESTRIP"},
      // NBT normals (GX_NRM_NBT, GX_NRM_NBT3 with its three indices) in formats 3 and 5: the
      // module's GX_SetVtxAttrFmt(GX_VTXFMTn, GX_VA_NBT, GX_NRM_NBT...) and its draws' format.
      {"scenes/coloured_cubes.json",
       "t=vertex:vtx=s16/auto:nrm=s8/nbt:clr=rgb565:uv=s16/auto:vat=3:draw=list",
       "GX_SetVtxAttrFmt(GX_VTXFMT3, GX_VA_NBT, GX_NRM_NBT, "},
      {"scenes/coloured_cubes.json",
       "lobe=xf-spec:view=object:vtx=s16/auto:nrm=s16/nbt3:clr=rgba4:vat=5:draw=indexed",
       "GX_SetVtxAttrFmt(GX_VTXFMT5, GX_VA_NBT, GX_NRM_NBT3, "}};
  for (const auto& [scene, variant, declares] : cases) {
    const fs::path c = dir / "stored_module.c";
    const test::RunResult r =
        test::run_ltrender("export gx " + (test::source_dir() / scene).string() + " --variant " +
                           variant + " --format module -o " + c.string());
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(test::read_file(c).find(declares), std::string::npos) << variant;
    EXPECT_NE(test::read_file(c).find("ltrender_draw_stored"), std::string::npos) << scene;
    for (const fs::path& ogc : checkouts) {
      const fs::path log = dir / "cc.log";
      EXPECT_EQ(std::system(compile_command(c, ogc, log).c_str()), 0)
          << scene << " against " << ogc << ":\n"
          << test::read_file(log);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Scenes, GxExportCompiles, ::testing::ValuesIn(export_scenes()),
                         [](const auto& info) { return test::test_param_name(info.param); });

}  // namespace
}  // namespace lt
