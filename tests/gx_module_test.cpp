// The module (`export gx --format module`, issue 26) does what the emulator does, frame after
// frame: for every demo scene, the exported module is compiled on the host (its maths is plain
// C; tests/gx_module_host/ stands in for libogc, printing each GX call as the program text the
// interpreter reads), its setup runs for 8 cameras and lights along a path, and its pass
// functions' calls drive ltrender's emulator. Each frame must be the very image ltrender renders
// when the scene itself is moved there (every pixel, every channel), and the module's t must be
// the t the emulator sends, bit for bit. The scene is first made what a game holds: float
// positions, normals, camera and lights (the module's inputs are f32). t=texgen:view=object's
// texture matrix, recomputed by the setup each frame from the meshes' centre, is held the same
// way: the frames it drives must be the emulator's.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <set>
#include <sstream>

#include "load/load_scene.h"
#include "paths/gx/generator.h"
#include "paths/gx/gx_variant.h"
#include "paths/gx/module/module_exporter.h"
#include "paths/gx/module/runtime/ltrender_gx_runtime.h"
#include "paths/gx/program/gx_name_table.h"
#include "paths/gx/program/pass_programs.h"
#include "paths/gx/vertex_stage.h"
#include "render/camera_path.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::gx {
namespace {

constexpr int kFrames = kCameraPathFrames;  // render/camera_path.h: the path every frame is on
constexpr int kSize = 96;

// The scene as a game holds it: every input of the module in f32.
void make_float(Scene& s) {
  for (SceneObject& o : s.objects) {
    for (auto& p : o.mesh.positions) p = rounded_to_float(p);
    for (auto& n : o.mesh.normals) n = rounded_to_float(n);
  }
  s.camera.eye = rounded_to_float(s.camera.eye);
  s.camera.target = rounded_to_float(s.camera.target);
  s.camera.up = rounded_to_float(s.camera.up);
  for (Light& l : s.lights) {
    l.position = rounded_to_float(l.position);
    l.direction = rounded_to_float(l.direction);
    l.color = rounded_to_float(l.color);
    l.translucency_scale = static_cast<float>(l.translucency_scale);
  }
}

// The host side: the module and the recorder compiled into one shared object.
class HostModule {
 public:
  HostModule(const test::TempDir& dir, const std::string& module_text) {
    std::ostringstream constants;
    std::set<std::string> seen;
    for (const GxName& n : kGxNames) {
      if (seen.insert(n.name).second) constants << "#define " << n.name << " " << n.value << "\n";
    }
    test::write_file(dir / "gx_constants.h", constants.str());
    const fs::path host = test::source_dir() / "tests" / "gx_module_host";
    fs::copy_file(host / "gccore.h", dir / "gccore.h", fs::copy_options::overwrite_existing);
    test::write_file(dir / "module.c", module_text);
    const fs::path so = dir / "module.so", log = dir / "cc.log";
    const std::string cc =
        "cc -std=c99 -O1 -ffp-contract=off -fPIC -shared -Wall -Wextra -Werror -I" +
        dir.path().string() + " " + (dir / "module.c").string() + " " +
        (host / "gx_host.c").string() + " -o " + so.string() + " -lm >" + log.string() + " 2>&1";
    compiled = std::system(cc.c_str()) == 0;
    compiler_output = test::read_file(log);
    if (compiled) handle_ = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  }
  ~HostModule() {
    if (handle_) dlclose(handle_);
  }
  template <typename F>
  F* get(const std::string& name) const {
    return reinterpret_cast<F*>(handle_ ? dlsym(handle_, name.c_str()) : nullptr);
  }
  bool compiled = false;
  std::string compiler_output;

 private:
  void* handle_ = nullptr;
};

using ViewFn = void(const ltr_camera*, ltr_view*);
using SetupFn = void(const ltr_view*, const ltr_light*, const ltr_mesh*, int, ltr_pass_state*);
using PassFn = void(ltr_pass_state*);
using FillTFn = void(const ltr_view*, const ltr_light*, int, const ltr_mesh*, float*);
using BeginFn = void(const char*);
using VoidFn = void();
using ProgramFn = const char*();

void copy3(const glm::dvec3& v, float out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(v[i]);
}

struct MeshArrays {
  std::vector<float> positions, normals;
  ltr_mesh mesh{};
};

MeshArrays arrays_of(const SceneObject& o) {
  MeshArrays m;
  for (size_t v = 0; v < o.mesh.positions.size(); ++v) {
    for (int i = 0; i < 3; ++i) {
      m.positions.push_back(static_cast<float>(o.mesh.positions[v][i]));
      m.normals.push_back(static_cast<float>(o.mesh.normals[v][i]));
    }
  }
  m.mesh.positions = m.positions.data();
  m.mesh.normals = m.normals.data();
  m.mesh.vertex_count = static_cast<int>(o.mesh.positions.size());
  return m;
}

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
  auto* view_of = host.get<ViewFn>("ltrender_view");
  auto* begin = host.get<BeginFn>("ltr_host_begin");
  auto* end = host.get<VoidFn>("ltr_host_end");
  auto* reset = host.get<VoidFn>("ltr_host_reset");
  auto* program = host.get<ProgramFn>("ltr_host_program");
  ASSERT_TRUE(view_of && begin && end && reset && program);
  const ScenePlan plan = plan_scene(base, variant);
  std::set<std::string> programs_seen, scales_seen;
  std::string previous_program;
  int stale_differs = 0;
  for (int k = 0; k < kFrames; ++k) {
    const Scene s = scene_on_camera_path(base, k);
    const std::string at = GetParam().scene + " frame " + std::to_string(k);
    ltr_camera camera;
    copy3(s.camera.eye, camera.eye);
    copy3(s.camera.target, camera.target);
    copy3(s.camera.up, camera.up);
    std::vector<ltr_light> lights(std::max<size_t>(s.lights.size(), 1));
    for (size_t l = 0; l < s.lights.size(); ++l) {
      copy3(s.lights[l].position, lights[l].position);
      copy3(s.lights[l].direction, lights[l].direction);
      copy3(s.lights[l].color, lights[l].color);
      lights[l].translucency_scale = static_cast<float>(s.lights[l].translucency_scale);
    }
    ltr_view view;
    view_of(&camera, &view);
    reset();
    const SceneView scene_view = SceneView::of(s);
    for (const MaterialPlan& m : plan.materials) {
      const std::string id = "ltrender_" + m.c_name;
      std::vector<MeshArrays> arrays;
      std::vector<size_t> objects;
      for (size_t o = 0; o < s.objects.size(); ++o) {
        if (s.objects[o].material != m.material) continue;
        arrays.push_back(arrays_of(s.objects[o]));
        objects.push_back(o);
      }
      std::vector<ltr_mesh> meshes;
      for (MeshArrays& a : arrays) {
        a.mesh.positions = a.positions.data();
        a.mesh.normals = a.normals.data();
        meshes.push_back(a.mesh);
      }
      std::vector<ltr_pass_state> state(m.passes.size());
      auto* setup = host.get<SetupFn>(id + "_setup");
      ASSERT_TRUE(setup) << id;
      setup(&view, lights.data(), meshes.data(), static_cast<int>(meshes.size()), state.data());
      for (const ltr_pass_state& st : state)
        scales_seen.insert(std::to_string(st.translucency_scale) + "/" +
                           std::to_string(st.diffuse_scale));
      for (size_t p = 0; p < m.passes.size(); ++p) {
        const std::string name = pass_function_name(m.c_name, static_cast<int>(p));
        auto* pass = host.get<PassFn>(name);
        ASSERT_TRUE(pass) << name;
        begin(name.c_str());
        pass(&state[p]);
        end();
        if (!m.passes[p].vertex.t) continue;
        // The t the module computes is the t the emulator sends (vertex_stage.h), bit for bit.
        auto* fill_t = host.get<FillTFn>(id + "_fill_t");
        ASSERT_TRUE(fill_t) << id;
        const size_t light = m.passes[p].figures.light;
        for (size_t i = 0; i < objects.size(); ++i) {
          const VertexStream stream = make_vertex_stream(s, s.objects[objects[i]], scene_view);
          std::vector<float> t(stream.position.size());
          fill_t(&view, lights.data(), static_cast<int>(light), &meshes[i], t.data());
          size_t differ = 0;
          for (size_t v = 0; v < t.size(); ++v) differ += t[v] != stream.t_per_light[light][v];
          EXPECT_EQ(differ, 0u) << at << " " << name << " object " << objects[i] << ": vertices "
                                << "whose t differs from the emulator's";
        }
      }
    }
    const std::string text = program();
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

// lobe=xf-spec fits its lobe per frame in double, which a module does not carry: one line naming
// the variant, exit 2, no file.
TEST(GxModuleExport, RefusesXfSpecNamingTheVariant) {
  test::TempDir dir;
  const fs::path out = dir / "m.c";
  const test::RunResult r = test::run_ltrender(
      "export gx " + (test::source_dir() / "scenes/ortho/backlit_sphere_ortho.json").string() +
      " --variant lobe=xf-spec --format module -o " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--variant"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("lobe=xf-spec"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(out));
}

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const std::string& s : test::json_files("scenes")) out.push_back({s, "t=vertex"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "t=vertex"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "t=texgen"});
  // The per-frame texture matrix of a constant V and L (object_view.h), under every camera and
  // light of the demo scenes.
  for (const std::string& s : test::json_files("scenes"))
    out.push_back({s, "t=texgen:view=object"});
  out.push_back({"scenes/ortho/backlit_sphere_ortho.json", "t=texgen:view=object"});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Scenes, GxModule, ::testing::ValuesIn(cases()), [](const auto& info) {
  return test::test_param_name(info.param.scene + "_" + info.param.variant);
});

}  // namespace
}  // namespace lt::gx
