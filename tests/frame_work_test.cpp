// The bench's work axis (report/frame_work.h): operations a frame executes, counted from what a
// path built and what was drawn. Checked against arithmetic by hand, against the reference's own
// coverage, against what the gx emulator counts as it draws, and against `budget`'s counts.
#include "report/frame_work.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <numeric>
#include <sstream>

#include "load/load_scene.h"
#include "paths/common/gbuffer.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

Scene demo_scene(const char* name) {
  return load_scene(test::source_dir() / "scenes" / name);
}

TEST(FrameWork, SumsEachMaterialsOperationsOverItsPixelsAndVertices) {
  const WorkModel model{"op", "vertex op", {{3, 2}, {0, 0}, {5, 1}}, {}};
  const SceneCoverage coverage{{100, 7, 10}, {20, 4, 6}};
  const auto w = frame_work(model, coverage);
  ASSERT_TRUE(w);
  EXPECT_EQ(w->pixel_ops, 3 * 100 + 5 * 10);
  EXPECT_EQ(w->vertex_ops, 2 * 20 + 1 * 6);
  EXPECT_EQ(w->total(), 350 + 46);
  EXPECT_EQ(w->pixel_operation, "op");
  // A path that counts nothing gets no figure, not a zero.
  EXPECT_FALSE(frame_work(WorkModel{{}, {}, {}, "why"}, coverage));
}

TEST(FrameWork, VerticesAreCountedPerMaterialOverItsObjects) {
  const Scene s = demo_scene("coloured_cubes.json");
  const SceneCoverage c = scene_coverage(s, {});
  ASSERT_EQ(c.vertices.size(), s.materials.size());
  double all = 0;
  for (const SceneObject& o : s.objects) all += static_cast<double>(o.mesh.positions.size());
  EXPECT_EQ(std::accumulate(c.vertices.begin(), c.vertices.end(), 0.0), all);
}

TEST(FrameWork, CoverageByMaterialAddsUpToTheReferencesCoverage) {
  const Scene s = demo_scene("coloured_cubes.json");
  RenderSession session(s, 160, 120);
  const std::vector<double> by_material = covered_pixels_by_material(session.context());
  const PathInfo& ref = find_path("reference");
  auto path = session.build(ref, resolve_variant(ref, ""));
  path->frame();
  const double covered = static_cast<double>(test::covered_pixels(path->result()));
  EXPECT_GT(covered, 0);
  EXPECT_EQ(std::accumulate(by_material.begin(), by_material.end(), 0.0), covered);
  size_t materials_seen = 0;
  for (double p : by_material) materials_seen += p > 0;
  EXPECT_GE(materials_seen, 2u);  // the cubes have materials of their own
}

// gx counts TEV stages and XF lights as its emulator runs them (FrameStats); the work model
// counts them from the programs and the coverage. The emulator runs the TEV for every pixel that
// passes the early depth test, as the console does, and the programs draw without culling: a
// sphere's back faces drawn before the front faces over them run it too. Each pixel of a convex
// mesh is covered by at most two faces, so the emulator's count is 1x to 2x the model's (the
// coverage of the two differs by the console's few silhouette pixels, < 0.2%).
TEST(FrameWork, GxWorkIsWhatTheEmulatorCountsAsItDraws) {
  const Scene s = demo_scene("backlit_sphere.json");
  RenderSession session(s, 160, 120);
  const SceneCoverage coverage = scene_coverage(s, covered_pixels_by_material(session.context()));
  const PathInfo& gx = find_path("gx");
  auto path = session.build(gx, resolve_variant(gx, ""));
  path->frame();
  const FrameStats stats = path->frame_stats();
  const auto w = frame_work(path->work(), coverage);
  ASSERT_TRUE(w);
  ASSERT_TRUE(stats.tev_stage_pixels && stats.xf_light_vertices);
  EXPECT_GE(*stats.tev_stage_pixels, w->pixel_ops * 0.998);
  EXPECT_LE(*stats.tev_stage_pixels, w->pixel_ops * 2.0);
  EXPECT_EQ(w->vertex_ops, *stats.xf_light_vertices);
  EXPECT_GT(w->pixel_ops, 0);
}

// arbfp's per-pixel and per-vertex operations are the instruction counts `budget` reports (of the
// printed text parsed back; the work model counts the generator's IR).
TEST(FrameWork, ArbfpCountsWhatTheBudgetCounts) {
  const Scene s = demo_scene("three_point_blob.json");
  RenderSession session(s, 64, 48);
  const PathInfo& arbfp = find_path("arbfp");
  const std::string variant = resolve_variant(arbfp, "");
  auto path = session.build(arbfp, variant);
  const budget::Report r = arbfp.budget(s, variant, "");
  const WorkModel model = path->work();
  size_t checked = 0;
  for (size_t m = 0; m < s.materials.size(); ++m) {
    const std::string prefix = "material " + s.materials[m].name + ": ";
    for (const budget::Item& p : r.items) {
      if (p.name == prefix + "fragment program") {
        EXPECT_EQ(model.by_material[m].per_pixel, p.used("alu") + p.used("tex"));
        ++checked;
      } else if (p.name == prefix + "vertex program") {
        EXPECT_EQ(model.by_material[m].per_vertex, p.used("instruction_slots"));
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 2u) << budget::to_text(r);
}

TEST(FrameWork, GlslSaysWhyItCountsNothing) {
  const Scene s = demo_scene("backlit_sphere.json");
  RenderSession session(s, 32, 24);
  const PathInfo& glsl = find_path("glsl");
  const WorkModel model = session.build(glsl, resolve_variant(glsl, ""))->work();
  EXPECT_TRUE(model.by_material.empty());
  EXPECT_FALSE(model.not_counted.empty());
}

}  // namespace
}  // namespace lt
