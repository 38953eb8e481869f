// Every port's error against the reference, on every demo scene, from one table:
// src/paths/bounds/path_bounds.json
// (rows: path, variant, scene or "*", max / mean / p99 LSB bounds, a reason). One parameterised
// test renders each (scene, path, variant) the bench would run and holds it to its row; another
// fails when a variant has no row, so a new path or variant cannot land without a stated bound.
// The bounds are measured (`ltrender bench scenes/*.json scenes/ortho/*.json scenes/maps/*.json`)
// with a margin, and the reason says why the error is what it is.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>

#include "load/load_scene.h"
#include "metrics/compare.h"
#include "paths/path_bounds.h"
#include "reference_cache.h"
#include "render/session.h"
#include "test_util.h"

namespace lt {
namespace {

// The table and its reader are the product's (paths/path_bounds.h): regress holds a new golden
// to the same rows.
using BoundRow = PathBound;

const std::vector<PathBound>& bound_rows() {
  return path_bounds();
}

const PathBound* find_row(const std::string& path, const std::string& variant,
                          const std::string& scene) {
  return find_path_bound(path, variant, scene);
}

struct BoundCase {
  std::string scene_file, path, variant;
};

void PrintTo(const BoundCase& c, std::ostream* os) {
  *os << c.scene_file << " " << c.path << " " << c.variant;
}

// What the bench runs: every port, every variant, every demo scene. The list is made from file
// names only: gtest builds it in every test process of the binary, and loading the scenes here
// (meshes, maps, the image module) cost 0.3 s in each of them (issue 28 measured it).
std::vector<BoundCase> bound_cases() {
  std::vector<BoundCase> out;
  std::vector<std::string> scenes = test::json_files("scenes");
  for (const std::string& s : test::json_files("scenes/ortho")) scenes.push_back(s);
  for (const std::string& s : test::json_files("scenes/maps")) scenes.push_back(s);
  for (const std::string& s : scenes) {
    for (const PathInfo& p : all_paths()) {
      if (p.role != PathRole::Port) continue;
      for (const VariantInfo& v : p.variants) out.push_back({s, p.name, v.name});
    }
  }
  return out;
}

// Why `c`'s path refuses its scene (gx t=texgen under perspective), or "" when it renders it.
std::string refusal(const BoundCase& c, const Scene& scene) {
  const PathInfo& info = find_path(c.path);
  return info.refusal(scene, c.variant);
}

std::string stem(const std::string& file) {
  return fs::path(file).stem().string();
}

TEST(Bounds, EveryVariantOnEveryDemoSceneHasARow) {
  std::map<std::string, Scene> scenes;
  for (const BoundCase& c : bound_cases()) {
    auto it = scenes.find(c.scene_file);
    if (it == scenes.end())
      it = scenes.emplace(c.scene_file, load_scene(test::source_dir() / c.scene_file)).first;
    if (!refusal(c, it->second).empty()) continue;
    EXPECT_NE(find_row(c.path, c.variant, stem(c.scene_file)), nullptr)
        << "src/paths/bounds/path_bounds.json has no row for " << c.path << " " << c.variant
        << " on " << stem(c.scene_file) << ": measure it (ltrender bench) and state why";
  }
  for (const BoundRow& r : bound_rows()) {
    EXPECT_FALSE(r.reason.empty()) << r.path << " " << r.variant << " " << r.scene;
    EXPECT_GT(r.max_lsb, 0) << r.path << " " << r.variant << " " << r.scene;
  }
}

class Bounded : public ::testing::TestWithParam<BoundCase> {};

// The scene of a case, read once a process: a batch runs every path and variant of a scene in a
// row, and each read its meshes again (a demo scene's PLY and OpenMesh's build of it).
const Scene& bounded_scene(const std::string& file) {
  static std::map<std::string, Scene> loaded;
  auto it = loaded.find(file);
  if (it == loaded.end()) it = loaded.emplace(file, load_scene(test::source_dir() / file)).first;
  return it->second;
}

TEST_P(Bounded, WithinItsRowOfTheReference) {
  const BoundCase& c = GetParam();
  const Scene& scene = bounded_scene(c.scene_file);
  // A variant that cannot be exact here is refused by render (tested in gx_path_test.cpp).
  if (const std::string why = refusal(c, scene); !why.empty()) GTEST_SKIP() << why;
  const BoundRow* row = find_row(c.path, c.variant, stem(c.scene_file));
  ASSERT_NE(row, nullptr) << "no row (see Bounds.EveryVariantOnEveryDemoSceneHasARow)";
  RenderSession session(scene, scene.width, scene.height);
  const Image reference = test::cached_reference(test::test_param_name(c.scene_file), [&] {
    auto ref = session.build(path_with_role(PathRole::GroundTruth), "");
    ref->frame();
    return ref->result();
  });
  const PathInfo& info = find_path(c.path);
  auto path = session.build(info, c.variant);
  path->frame();
  const Image img = path->result();
  EXPECT_EQ(test::non_finite(img), 0u) << "no NaN or Inf ever reaches an image";
  const Comparison cmp = compare_images(
      img, reference, path->float_output() ? TestEncoding::kFloat : TestEncoding::kUnorm8,
      TestEncoding::kFloat, Coverage::kBoth);
  // The GL paths rasterise as the reference does, pixel for pixel; the gx path as the console
  // does (9/16 of a pixel: rasteriser.h), which moves silhouette pixels: a thin line, measured
  // at most 0.142% of the covered pixels over every gx case (docs/testing.md "Error bounds").
  if (c.path == "gx")
    EXPECT_LE(cmp.mismatch.percent(), 0.5) << cmp.mismatch.reference_only << " reference-only, "
                                           << cmp.mismatch.test_only << " test-only";
  else
    EXPECT_EQ(cmp.mismatch.reference_only + cmp.mismatch.test_only, 0u);
  // What a row is set from (max x 1.2 + 0.1, mean x 1.2 + 0.02, rounded up:
  // src/paths/bounds/path_bounds.json).
  std::printf("measured %s %s %s: max %.3f mean %.3f p99 %.3f image_max %.3f mismatch %.3f%%\n",
              c.path.c_str(), c.variant.c_str(), stem(c.scene_file).c_str(), cmp.covered.max_lsb,
              cmp.covered.mean_lsb, cmp.covered.p99_lsb, cmp.image.max_lsb, cmp.mismatch.percent());
  EXPECT_GT(cmp.covered.pixels, reference.pixel_count() / 50) << "the scene shows too little";
  std::string broken;
  for (const std::string& b : bound_violations(*row, cmp)) broken += b + "; ";
  EXPECT_TRUE(broken.empty()) << broken << row->reason << "; max at " << cmp.covered.max_x << ","
                              << cmp.covered.max_y;
}

INSTANTIATE_TEST_SUITE_P(Demo, Bounded, ::testing::ValuesIn(bound_cases()), [](const auto& info) {
  return test::test_param_name(stem(info.param.scene_file) + "__" + info.param.path + "__" +
                               info.param.variant);
});

}  // namespace
}  // namespace lt
