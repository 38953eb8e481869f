// A module (`export gx --format module`) compiled and run on the host, as a game would run it on
// the console: tests/gx_module_test.cpp holds the frames it drives to the emulator's, and
// tests/dolphin_judge_test.cpp plays them in Dolphin. gccore.h and gx_host.c here stand in for
// libogc: each GX call prints itself as the program text ltrender's interpreter reads.
#pragma once

#include <dlfcn.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "../test_util.h"
#include "gx/program/gx_name_table.h"
#include "gx/program/pass_programs.h"
#include "paths/gx/generator.h"
#include "paths/gx/module/runtime/ltrender_gx_runtime.h"
#include "render/camera_path.h"
#include "scene/scene.h"

namespace lt::gx::test_module {

// The scene as a game holds it: every input of the module in f32.
inline void make_float(Scene& s) {
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

// libogc's stand-in, compiled once a test process: it, gccore.h and the constants header are
// the same for every module (0.2 s of the compiler a module otherwise). Empty if it failed, with
// the compiler's output in `log`.
struct HostObject {
  fs::path dir, object;
  std::string log;
  HostObject() {
    dir = fs::temp_directory_path() / ("lt_gx_host_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::ostringstream constants;
    std::set<std::string> seen;
    for (const GxName& n : kGxNames) {
      if (seen.insert(n.name).second) constants << "#define " << n.name << " " << n.value << "\n";
    }
    test::write_file(dir / "gx_constants.h", constants.str());
    const fs::path host = test::source_dir() / "tests" / "gx_module_host";
    fs::copy_file(host / "gccore.h", dir / "gccore.h", fs::copy_options::overwrite_existing);
    const fs::path out = dir / "gx_host.o", log_file = dir / "cc.log";
    const std::string cc = "cc " + std::string(kHostFlags) + " -c -I" + dir.string() + " " +
                           (host / "gx_host.c").string() + " -o " + out.string() + " >" +
                           log_file.string() + " 2>&1";
    if (std::system(cc.c_str()) == 0) object = out;
    log = test::read_file(log_file);
  }
  ~HostObject() {
    std::error_code ignored;
    fs::remove_all(dir, ignored);
  }
  // -O0: the compiler was ~45% of a module case's CPU at -O1 (perf; teapot_vertex's case 3.1 s
  // of CPU at -O1, 2.4 s at -O0), and on x86-64 each float and double operation rounds as IEEE
  // says at any level; -ffp-contract=off keeps a*b+c two roundings, as the runtime's header asks.
  static constexpr const char* kHostFlags =
      "-std=c99 -O0 -ffp-contract=off -fPIC -Wall -Wextra -Werror";
};

inline const HostObject& host_object() {
  static const HostObject host;
  return host;
}

// The host side: the module and the recorder compiled into one shared object.
class HostModule {
 public:
  HostModule(const test::TempDir& dir, const std::string& module_text) {
    const HostObject& host = host_object();
    if (host.object.empty()) {
      compiler_output = host.log;
      return;
    }
    test::write_file(dir / "module.c", module_text);
    const fs::path so = dir / "module.so", log = dir / "cc.log";
    const std::string cc = "cc " + std::string(HostObject::kHostFlags) + " -shared -I" +
                           host.dir.string() + " " + (dir / "module.c").string() + " " +
                           host.object.string() + " -o " + so.string() + " -lm >" + log.string() +
                           " 2>&1";
    compiled = std::system(cc.c_str()) == 0;
    compiler_output = test::read_file(log);
    if (compiled) handle_ = dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
    // What a game calls once before its first draw: it opens the module's TPL, from which every
    // pass takes its textures (module_textures.h).
    if (auto* open_textures = get<void()>("ltrender_flush_textures")) open_textures();
  }
  ~HostModule() {
    if (handle_) dlclose(handle_);
  }
  HostModule(const HostModule&) = delete;
  HostModule& operator=(const HostModule&) = delete;
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

inline void copy3(const glm::dvec3& v, float out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = static_cast<float>(v[i]);
}

struct MeshArrays {
  std::vector<float> positions, normals;
  ltr_mesh mesh{};
};

inline MeshArrays arrays_of(const SceneObject& o) {
  MeshArrays m;
  for (size_t v = 0; v < o.mesh.positions.size(); ++v) {
    for (int i = 0; i < 3; ++i) {
      m.positions.push_back(static_cast<float>(o.mesh.positions[v][i]));
      m.normals.push_back(static_cast<float>(o.mesh.normals[v][i]));
    }
  }
  m.mesh.vertex_count = static_cast<int>(o.mesh.positions.size());
  return m;
}

// What a frame gave one material: its meshes (scene object indices alongside) and pass states.
struct MaterialFrame {
  const MaterialPlan* plan = nullptr;
  std::vector<size_t> objects;
  std::vector<ltr_mesh> meshes;
  std::vector<ltr_pass_state> states;
};

// One frame as a game runs it: the view of the scene's camera, the lights in world space, each
// material's setup over its meshes, then each pass function with its state. Returns the program
// text the pass functions printed (empty when a function is missing: ADD_FAILURE says which);
// `each` (may be empty) sees every material's frame, with the view and lights, before the next.
inline std::string drive_frame(
    const HostModule& host, const ScenePlan& plan, const Scene& s,
    const std::function<void(const MaterialFrame&, const ltr_view&, const std::vector<ltr_light>&)>&
        each = {}) {
  auto* view_of = host.get<ViewFn>("ltrender_view");
  auto* begin = host.get<BeginFn>("ltr_host_begin");
  auto* end = host.get<VoidFn>("ltr_host_end");
  auto* reset = host.get<VoidFn>("ltr_host_reset");
  auto* program = host.get<ProgramFn>("ltr_host_program");
  if (!(view_of && begin && end && reset && program)) {
    ADD_FAILURE() << "the host module lacks the view or the recorder";
    return "";
  }
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
  for (const MaterialPlan& m : plan.materials) {
    const std::string id = "ltrender_" + m.c_name;
    MaterialFrame f;
    f.plan = &m;
    std::vector<MeshArrays> arrays;
    for (size_t o = 0; o < s.objects.size(); ++o) {
      if (s.objects[o].material != m.material) continue;
      arrays.push_back(arrays_of(s.objects[o]));
      f.objects.push_back(o);
    }
    for (MeshArrays& a : arrays) {
      a.mesh.positions = a.positions.data();
      a.mesh.normals = a.normals.data();
      f.meshes.push_back(a.mesh);
    }
    f.states.resize(m.passes.size());
    auto* setup = host.get<SetupFn>(id + "_setup");
    if (!setup) {
      ADD_FAILURE() << "the module has no " << id << "_setup";
      return "";
    }
    setup(&view, lights.data(), f.meshes.data(), static_cast<int>(f.meshes.size()),
          f.states.data());
    for (size_t p = 0; p < m.passes.size(); ++p) {
      const std::string name = pass_function_name(m.c_name, static_cast<int>(p));
      auto* pass = host.get<PassFn>(name);
      if (!pass) {
        ADD_FAILURE() << "the module has no " << name;
        return "";
      }
      begin(name.c_str());
      pass(&f.states[p]);
      end();
    }
    if (each) each(f, view, lights);
  }
  return program();
}

}  // namespace lt::gx::test_module
