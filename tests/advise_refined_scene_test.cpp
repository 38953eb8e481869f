// `advise -o DIR` writes a refinement that holds the budget as meshes and a scene
// (advise/refined_scene.h, docs/advise.md "Mesh density"): the scene loads back, has the
// vertices advise reported, and rendering it gives the error advise reported.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "advise/material_error.h"
#include "core/build_paths.h"
#include "load/load_scene.h"
#include "metrics/compare.h"
#include "paths/common/gbuffer.h"
#include "paths/path.h"
#include "render/evaluate.h"
#include "render/session.h"
#include "scene/scene.h"
#include "test_util.h"

namespace lt::advise {
namespace {

// baked_blob through the combiners is ~76 LSB off at its silhouette (issue 29); a refinement to
// 8 LSB holds within a few hundred vertices at 48 pixels wide. --max-vertices 12000 stops the
// uniform comparison after one step (40962 vertices), which keeps the test cheap.
TEST(AdviseRefinedScene, TheWrittenSceneRendersTheErrorAdviseReported) {
  test::TempDir dir;
  const fs::path scene_file = lt::build_paths::source_dir() / "scenes" / "baked_blob.json";
  const fs::path out = dir / "out", report = dir / "advise.json";
  const test::RunResult r =
      test::run_ltrender("advise " + scene_file.string() +
                         " --target gl13-2units --max-lsb 8 --width 48 --max-vertices 12000 "
                         "--json " +
                         report.string() + " -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const nlohmann::json j = nlohmann::json::parse(test::read_file(report));
  const nlohmann::json& refinement = j["materials"][0]["refinement"];
  ASSERT_TRUE(refinement["holds_at"].is_number()) << refinement.dump();
  const nlohmann::json& step = refinement["adaptive"][refinement["holds_at"].get<size_t>()];
  const std::string variant = refinement["variant"];

  ASSERT_TRUE(fs::exists(out / "skin_object0.ply")) << r.out;
  ASSERT_TRUE(fs::exists(out / "refined.json")) << r.out;
  EXPECT_TRUE(fs::exists(out / "skin_0.comb")) << r.out;  // the refinement's program
  const Scene original = load_scene(scene_file);
  const Scene refined = load_scene(out / "refined.json");
  ASSERT_EQ(refined.objects.size(), 1u);
  const TriangleMesh& m = refined.objects[0].mesh;
  EXPECT_EQ(m.positions.size(), step["vertices"].get<size_t>());
  EXPECT_GT(m.positions.size(), original.objects[0].mesh.positions.size());
  ASSERT_EQ(m.colors.size(), m.positions.size());  // the baked thickness came along
  // In world space, transform dropped: the original's vertices are the first of the refined
  // mesh (refinement appends), where the original scene put them (the file's double positions).
  for (size_t v = 0; v < original.objects[0].mesh.positions.size(); v += 97)
    ASSERT_EQ(m.positions[v], original.objects[0].mesh.positions[v]) << v;

  // Rendered as advise measures a candidate: the scene's reference, the material's pixels.
  const int width = j["width"], height = j["height"];
  RenderSession session(refined, width, height);
  const Image reference = render_reference(session);
  const std::vector<int> material = material_per_pixel(session.context());
  auto path = session.build(find_path("combiners"), variant, {});
  path->frame();
  const Comparison c =
      compare_material(path->result(), reference, test_encoding(*path), material, 0);
  EXPECT_EQ(non_finite_pixels(c), 0u);
  EXPECT_LE(c.covered.max_lsb, 8.0);
  // The file holds normals and colours as float (advise held them in double): the figures can
  // move by a rounding, no more.
  EXPECT_NEAR(c.covered.max_lsb, step["error"]["max"].get<double>(), 0.01);
  EXPECT_NEAR(c.covered.mean_lsb, step["error"]["mean"].get<double>(), 0.01);
}

}  // namespace
}  // namespace lt::advise
