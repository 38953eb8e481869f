// Scene loading for the arbfp and budget tests. The demo and hard scenes name meshes under
// meshes/, which are generated files (`ltrender meshgen meshes`); when a checkout lacks them the
// scenes are loaded from a per-process copy with freshly generated meshes, so these tests check
// the path rather than the state of the checkout.
#pragma once

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "gl/program.h"
#include "load/load_scene.h"
#include "arb/arb_mesa_counts.h"
#include "paths/path.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::test {

inline fs::path generated_scene_root() {
  static const fs::path root = [] {
    const fs::path dir =
        fs::temp_directory_path() / ("lt_arb_scenes_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy(source_dir() / "scenes", dir / "scenes", fs::copy_options::recursive);
    const RunResult r = run_ltrender("meshgen " + (dir / "meshes").string());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return dir;
  }();
  // Removed when the test process exits.
  static const struct Cleanup {
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(root, ec);
    }
  } cleanup;
  return root;
}

// `relative` like "scenes/backlit_sphere.json".
inline Scene load_test_scene(const std::string& relative) {
  try {
    return load_scene(source_dir() / relative);
  } catch (const InputError&) {
    return load_scene(generated_scene_root() / relative);
  }
}

}  // namespace lt::test

namespace lt::test {
// The file to hand to the CLI for `relative`: the checkout's, or the generated copy's.
inline fs::path test_scene_path(const std::string& relative) {
  try {
    load_scene(source_dir() / relative);
    return source_dir() / relative;
  } catch (const InputError&) {
    return generated_scene_root() / relative;
  }
}
}  // namespace lt::test

namespace lt::test {
// One frame of `path` into a float target (no 8-bit rounding): RGBA, bottom row first.
inline std::vector<float> frame_in_float_target(Path& path, int width, int height) {
  gl::FloatTarget target(width, height, 1);
  target.bind();
  path.frame();
  glFinish();
  std::vector<float> px;
  target.read(0, px);
  target.unbind();
  return px;
}
}  // namespace lt::test

namespace lt::test {
// Mesa accepts a generated fragment program's text, and its native counts agree with `counts`
// (the counter's) on ALU, TEX and temporaries. Needs a current GL context.
inline void expect_mesa_counts_agree(const std::string& fragment,
                                     const budget::ProgramCounts& counts, const std::string& what) {
  const arbfp::MesaCounts mesa = arbfp::mesa_counts(budget::ProgramKind::Fragment, fragment);
  ASSERT_TRUE(mesa.accepted) << what << ": " << mesa.error;
  EXPECT_EQ(mesa.native.alu, counts.alu) << what;
  EXPECT_EQ(mesa.native.tex, counts.tex) << what;
  EXPECT_EQ(mesa.native.temporaries, counts.temporaries) << what;
}
}  // namespace lt::test
