// `ltrender sweep` (report/sweep.h) and the camera path it and the GxModule test share
// (render/camera_path.h). The sweep's figures are held to a frame rendered and compared here
// through render/evaluate.h directly, and the path to the angles its comment states.
#include "report/sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

#include "load/load_scene.h"
#include "render/camera_path.h"
#include "render/evaluate.h"
#include "test_util.h"

namespace lt {
namespace {

double degrees_between(const glm::dvec3& a, const glm::dvec3& b) {
  const double c = glm::dot(glm::normalize(a), glm::normalize(b));
  return std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / glm::pi<double>();
}

TEST(CameraPath, OrbitsTheEyeSeventyDegreesAndThePointLightsFiftyTheOtherWay) {
  const Scene base = load_scene(test::source_dir() / "scenes/three_point_blob.json");
  const Scene first = scene_on_camera_path(base, 0);
  const Scene last = scene_on_camera_path(base, kCameraPathFrames - 1);
  const glm::dvec3 target = base.camera.target;
  EXPECT_EQ(first.camera.eye, base.camera.eye);  // frame 0 is the scene as it is
  const glm::dvec3 up = glm::normalize(base.camera.up);
  // Angles about the up axis: in the plane the rotation turns in.
  auto flat = [&](const glm::dvec3& v) { return v - up * glm::dot(v, up); };
  EXPECT_NEAR(degrees_between(flat(last.camera.eye - target), flat(base.camera.eye - target)), 70.0,
              1e-3);
  // The eye keeps its distance to the target (a rotation), within float.
  EXPECT_NEAR(glm::length(last.camera.eye - target), glm::length(base.camera.eye - target), 1e-5);
  ASSERT_FALSE(base.lights.empty());
  for (size_t l = 0; l < base.lights.size(); ++l) {
    ASSERT_EQ(base.lights[l].type, Light::Type::Point);
    // 50 degrees, and the other way than the eye.
    const glm::dvec3 a = flat(base.lights[l].position - target),
                     b = flat(last.lights[l].position - target);
    if (glm::length(a) < 1e-6) continue;
    EXPECT_NEAR(degrees_between(a, b), 50.0, 1e-3) << l;
    const glm::dvec3 ea = flat(base.camera.eye - target), eb = flat(last.camera.eye - target);
    EXPECT_LT(glm::dot(glm::cross(a, b), up) * glm::dot(glm::cross(ea, eb), up), 0.0) << l;
    EXPECT_NEAR(last.lights[l].color.r, static_cast<float>(base.lights[l].color.r * 1.6), 1e-6);
  }
}

// One frame: the sweep's row is the bench's compare of the scene as it is.
TEST(Sweep, OneFrameIsTheComparisonOfTheSceneItself) {
  const fs::path file = test::source_dir() / "scenes/backlit_sphere.json";
  SweepOptions o;
  o.scenes = {file};
  o.frames = 1;
  o.width = 64;
  o.height = 48;
  o.variants = VariantSelection::Defaults;
  const std::vector<SweepRow> rows = run_sweep(o);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].variant, "t=vertex");
  EXPECT_EQ(rows[0].frames, 1);
  Scene scene = load_scene(file);
  scene.width = 64;
  scene.height = 48;
  RenderSession session(scene, 64, 48);
  const Image reference = render_reference(session);
  auto path = session.build(find_path("gx"), "t=vertex");
  path->frame();
  const ErrorStats e = compare_with_reference(*path, reference).covered;
  EXPECT_GT(e.pixels, 0u);
  EXPECT_DOUBLE_EQ(rows[0].max_lsb, e.max_lsb);
  EXPECT_NEAR(rows[0].mean_lsb, e.mean_lsb, 1e-12);
  EXPECT_DOUBLE_EQ(rows[0].p99_lsb, e.p99_lsb);
}

// Over frames: the max is at least each frame's, a refused variant says so, and the table
// has a line per row.
TEST(Sweep, TheFramesMaxCoversEveryFrameAndRefusalsAreListed) {
  const fs::path file = test::source_dir() / "scenes/backlit_sphere.json";
  SweepOptions o;
  o.scenes = {file};
  o.frames = 2;
  o.width = 48;
  o.height = 36;
  const std::vector<SweepRow> two = run_sweep(o);
  o.frames = 1;
  const std::vector<SweepRow> one = run_sweep(o);
  ASSERT_EQ(two.size(), one.size());
  bool refused = false;
  for (size_t i = 0; i < two.size(); ++i) {
    if (!two[i].refused.empty()) {
      refused = refused || two[i].variant == "t=texgen";
      EXPECT_EQ(two[i].frames, 0) << two[i].variant;
      continue;
    }
    EXPECT_EQ(two[i].frames, 2) << two[i].variant;
    EXPECT_GE(two[i].max_lsb, one[i].max_lsb) << two[i].variant;
    EXPECT_GE(two[i].p99_lsb, one[i].p99_lsb) << two[i].variant;
  }
  EXPECT_TRUE(refused) << "t=texgen is refused under a perspective camera";
  const std::string table = sweep_markdown(two);
  EXPECT_EQ(static_cast<size_t>(std::count(table.begin(), table.end(), '\n')), two.size() + 2);
  EXPECT_NE(table.find("| backlit_sphere | `t=texgen` | refused"), std::string::npos) << table;
}

// --light-range D: each variant a second time with :light-range=D, right after it; the declared
// bound changes the TEV scales of a scene with point lights, so the figures differ.
TEST(Sweep, ALightRangeAddsTheDeclaredRowOfEachVariant) {
  SweepOptions o;
  o.scenes = {test::source_dir() / "scenes/coloured_cubes.json"};
  o.frames = 2;
  o.width = 48;
  o.height = 36;
  o.variants = VariantSelection::Defaults;
  o.light_range = "0";
  const std::vector<SweepRow> rows = run_sweep(o);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].variant, "t=vertex");
  EXPECT_EQ(rows[1].variant, "t=vertex:light-range=0");
  EXPECT_EQ(rows[1].frames, 2);
  EXPECT_NE(rows[0].mean_lsb, rows[1].mean_lsb);
}

TEST(SweepCli, OneOfWidthAndHeightIsBadInput) {
  const test::RunResult r = test::run_ltrender(
      "sweep " + (test::source_dir() / "scenes/backlit_sphere.json").string() + " --width 32");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find("--width/--height"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
}

}  // namespace
}  // namespace lt
