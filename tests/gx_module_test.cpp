// The module (`export gx --format module`, issue 26) does what the emulator does, frame after
// frame: for every demo scene, the exported module is compiled on the host (its maths is plain
// C; tests/gx_module_host/ stands in for libogc, printing each GX call as the program text the
// interpreter reads), its setup runs for 8 cameras and lights along a path, and its pass
// functions' calls drive ltrender's emulator. Each frame must be the very image ltrender renders
// when the scene itself is moved there (every pixel, every channel), and the module's t must be
// the t the emulator sends, bit for bit. The scene is first made what a game holds: float
// positions, normals, camera and lights (the module's inputs are f32). t=texgen:view=object's
// texture matrix, recomputed by the setup each frame from the meshes' centre, is held the same
// way: the frames it drives must be the emulator's, and so must lobe=xf-spec's (:view=object),
// whose specular light and fitted lobe the setup recomputes each frame.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>

#include "gx/program/pass_programs.h"
#include "gx_module_host/host_module.h"
#include "load/load_scene.h"
#include "model/rational_fit.h"
#include "model/translucency.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/module/module_exporter.h"
#include "paths/gx/module/runtime/ltrender_gx_runtime.h"
#include "paths/gx/scene_vertices.h"
#include "render/camera_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::gx::test_module {
namespace {

constexpr int kFrames = kCameraPathFrames;  // render/camera_path.h: the path every frame is on
constexpr int kSize = 96;

struct Case {
  std::string scene, variant;
};
void PrintTo(const Case& c, std::ostream* out) {
  *out << c.scene << " --variant " << c.variant;
}

class GxModule : public ::testing::TestWithParam<Case> {};

TEST_P(GxModule, DrivesTheEmulatorToTheDirectlyRenderedFrameAlongAPath) {
  Scene base = load_scene(test::source_dir() / GetParam().scene);
  make_float(base);
  const GxVariant variant = parse_gx_variant(GetParam().variant);
  test::TempDir dir;
  const HostModule host(dir, export_module(base, variant, GetParam().scene));
  ASSERT_TRUE(host.compiled) << host.compiler_output;
  const ScenePlan plan = plan_scene(base, variant);
  std::set<std::string> programs_seen, scales_seen;
  std::string previous_program;
  int stale_differs = 0;
  for (int k = 0; k < kFrames; ++k) {
    const Scene s = scene_on_camera_path(base, k);
    const std::string at = GetParam().scene + " frame " + std::to_string(k);
    const SceneView scene_view = SceneView::of(s);
    auto check = [&](const MaterialFrame& f, const ltr_view& view,
                     const std::vector<ltr_light>& lights) {
      const MaterialPlan& m = *f.plan;
      for (const ltr_pass_state& st : f.states)
        scales_seen.insert(std::to_string(st.translucency_scale) + "/" +
                           std::to_string(st.diffuse_scale));
      for (size_t p = 0; p < m.passes.size(); ++p) {
        if (!m.passes[p].vertex.t) continue;
        // The t the module computes is the t the emulator sends (vertex_stage.h), bit for bit.
        auto* fill_t = host.get<FillTFn>("ltrender_" + m.c_name + "_fill_t");
        ASSERT_TRUE(fill_t) << m.c_name;
        const size_t light = m.passes[p].figures.light;
        for (size_t i = 0; i < f.objects.size(); ++i) {
          const VertexStream stream = make_vertex_stream(s, s.objects[f.objects[i]], scene_view);
          std::vector<float> t(stream.position.size());
          fill_t(&view, lights.data(), static_cast<int>(light), &f.meshes[i], t.data());
          size_t differ = 0;
          for (size_t v = 0; v < t.size(); ++v) differ += t[v] != stream.t_per_light[light][v];
          EXPECT_EQ(differ, 0u) << at << " pass " << p << " object " << f.objects[i]
                                << ": vertices whose t differs from the emulator's";
        }
      }
    };
    const std::string text = drive_frame(host, plan, s, check);
    ASSERT_FALSE(text.empty()) << at;
    programs_seen.insert(text);
    const fs::path file = dir / ("frame" + std::to_string(k) + ".c");
    test::write_file(file, text);
    const Image direct = render_scene(s, "gx", GetParam().variant, kSize, kSize);
    const Image driven = render_scene(s, "gx", GetParam().variant, kSize, kSize, {file.string()});
    ASSERT_EQ(direct.rgba.size(), driven.rgba.size());
    size_t differ = 0;
    for (size_t i = 0; i < direct.rgba.size(); ++i) differ += direct.rgba[i] != driven.rgba[i];
    EXPECT_EQ(differ, 0u) << at << ": channel values where the module-driven frame differs";
    // The test can fail: the state of the frame before is not this frame's.
    if (!previous_program.empty() && stale_differs == 0) {
      const fs::path stale = dir / "stale.c";
      test::write_file(stale, previous_program);
      const Image old = render_scene(s, "gx", GetParam().variant, kSize, kSize, {stale.string()});
      stale_differs += old.rgba != direct.rgba;
    }
    previous_program = text;
  }
  // What the path exercised: the (translucency / diffuse) TEV scales the setup chose.
  std::cout << GetParam().scene << ": TEV scales (translucency stage/last stage) along the path:";
  for (const std::string& sc : scales_seen) std::cout << " " << sc;
  std::cout << "\n";
  EXPECT_EQ(programs_seen.size(), static_cast<size_t>(kFrames)) << "every frame sets its own state";
  EXPECT_GT(stale_differs, 0) << "a frame drawn with the frame before's state looks the same";
}

// lobe=xf-spec's fit in C (ltr_fit_lobe) is model::fit_rational22 in C++, coefficient for
// coefficient, on curves whose fit takes each branch: a steep lobe, a flat one (p = 0), a lobe cut
// off inside [0, |d|] (c0 near 0), one fully saturated (c0 > 1 + |d|), d = 0 (the constant).
TEST(GxModuleFit, IsTheEmulatorsFitBitForBit) {
  test::TempDir dir;
  const HostModule host(
      dir, export_module(load_scene(test::source_dir() / "scenes/ortho/backlit_sphere_ortho.json"),
                         parse_gx_variant("lobe=xf-spec"), "backlit_sphere_ortho"));
  ASSERT_TRUE(host.compiled) << host.compiler_output;
  using FitFn = void(double, double, double, double, double, double, ltr_rational*);
  auto* fit = host.get<FitFn>("ltr_fit_lobe");
  ASSERT_TRUE(fit);
  struct Curve {
    double c0, d, a, s, p;
  };
  const Curve curves[] = {{0.6, 0.4, 0.1, 1.0, 8.0},   {0.6, 0.4, 0.1, 1.0, 0.0},
                          {0.05, -0.5, 0.2, 0.7, 3.0}, {1.6, 0.3, 0.1, 1.0, 8.0},
                          {0.3, 0.0, 0.1, 1.0, 2.0},   {-0.2, 0.9, 0.0, 1.5, 16.0}};
  for (const Curve& c : curves) {
    const double sign = c.d >= 0 ? -1.0 : 1.0;
    const model::RationalFit want = model::fit_rational22(
        [&](double x) {
          return (c.a + c.s * model::lobe(std::clamp(c.c0 + sign * x, 0.0, 1.0), c.p)) /
                 (c.a + c.s);
        },
        std::abs(c.d));
    ltr_rational got{};
    fit(c.c0, sign, std::abs(c.d), c.a, c.s, c.p, &got);
    for (size_t i = 0; i < 3; ++i) {
      EXPECT_EQ(got.a[i], want.r.a[i])
          << "c0 " << c.c0 << " d " << c.d << " p " << c.p << " a" << i;
      EXPECT_EQ(got.k[i], want.r.k[i])
          << "c0 " << c.c0 << " d " << c.d << " p " << c.p << " k" << i;
    }
  }
}

// :light-range=0 declares the bound every scene keeps (att <= 1 / kc, N.L <= 1), so along the path
// no TEV scale it chooses is below the scan's (which could only saturate more), and on a scene
// whose point lights stay away from the objects some are above it: that is its cost.
TEST(GxLightRange, TheSafeBoundNeverChoosesASmallerScaleThanTheScan) {
  for (const std::string& file : test::json_files("scenes")) {
    const Scene base = load_scene(test::source_dir() / file);
    int larger = 0;
    for (int k = 0; k < kFrames; ++k) {
      const Scene s = scene_on_camera_path(base, k);
      const ScenePlan scan = plan_scene(s, parse_gx_variant("t=vertex"));
      const ScenePlan bound = plan_scene(s, parse_gx_variant("t=vertex:light-range=0"));
      ASSERT_EQ(scan.materials.size(), bound.materials.size());
      for (size_t m = 0; m < scan.materials.size(); ++m) {
        ASSERT_EQ(scan.materials[m].passes.size(), bound.materials[m].passes.size());
        for (size_t p = 0; p < scan.materials[m].passes.size(); ++p) {
          const PassFigures& a = scan.materials[m].passes[p].figures;
          const PassFigures& b = bound.materials[m].passes[p].figures;
          EXPECT_GE(b.diffuse_scale, a.diffuse_scale) << file << " frame " << k << " pass " << p;
          EXPECT_GE(b.translucency_scale, a.translucency_scale)
              << file << " frame " << k << " pass " << p;
          larger +=
              b.diffuse_scale > a.diffuse_scale || b.translucency_scale > a.translucency_scale;
        }
      }
    }
    if (file.find("coloured_cubes") != std::string::npos)
      EXPECT_GT(larger, 0) << file << ": the declared bound chose no larger scale than the scan";
  }
}

// --light-range takes a distance >= 0: anything else is one line naming it, exit 2, no file.
TEST(GxModuleExport, RefusesALightRangeThatIsNoDistance) {
  test::TempDir dir;
  const fs::path out = dir / "m.c";
  const test::RunResult r = test::run_ltrender(
      "export gx " + (test::source_dir() / "scenes/coloured_cubes.json").string() +
      " --light-range -2 --format module -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("light-range=-2"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

std::vector<Case> module_cases() {
  std::vector<Case> out;
  for (const std::string& s : test::json_files("scenes")) out.push_back({s, "t=vertex"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "t=vertex"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "t=texgen"});
  // The per-frame texture matrix of a constant V and L (object_view.h), under every camera and
  // light of the demo scenes.
  for (const std::string& s : test::json_files("scenes"))
    out.push_back({s, "t=texgen:view=object"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "t=texgen:view=object"});
  // The XF specular light's direction, position and lobe fitted again each frame (ltr_fit_lobe).
  for (const std::string& s : test::json_files("scenes"))
    out.push_back({s, "lobe=xf-spec:view=object"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "lobe=xf-spec"});
  // A declared light range instead of the scan (ltr_declared_range), on the two scenes with point
  // lights: the safe bound D = 0, and a tighter D = 1.5 with the XF specular light.
  out.push_back({"scenes/coloured_cubes.json", "t=vertex:light-range=0"});
  out.push_back({"scenes/three_point_blob.json", "lobe=xf-spec:view=object:light-range=1.5"});
  // A mipmapped albedo map: the module takes its chain from the TPL (TPL_GetTexture's
  // GX_InitTexObjLOD from the header, then the pass's own).
  out.push_back({"scenes/albedo_checker.json", "t=vertex:mip=lin:mip-bias=2"});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, GxModule, ::testing::ValuesIn(module_cases()),
                         [](const auto& info) {
                           return test::test_param_name(info.param.scene + "_" +
                                                        info.param.variant);
                         });

}  // namespace
}  // namespace lt::gx::test_module
