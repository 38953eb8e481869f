// `bench --jobs N` (cli/bench_jobs.h): the scenes shared out over job processes make the report
// one process makes. Rendering is deterministic, so every row's error and image are the same to
// the byte whichever process rendered it; only the timings may differ.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/cpu_affinity.h"
#include "test_util.h"

namespace lt {
namespace {

// Two small scenes that differ (a light from the back, from the side): rows of the one must not
// turn up as rows of the other.
void write_two_scenes(const fs::path& dir) {
  test::write_file(dir / "quad.obj", test::quad_obj());
  for (const auto& [name, direction] :
       {std::pair<const char*, const char*>{"back", "[0.3, 0, 1]"}, {"side", "[1, 0.4, 0.2]"}}) {
    test::write_file(dir / (std::string(name) + ".json"), std::string(R"({
    "image": {"width": 48, "height": 32},
    "camera": {"eye": [0, 0, 4], "target": [0, 0, 0], "fov_y_deg": 40},
    "materials": {"m": {"albedo": [0.8, 0.6, 0.4],
                        "translucency": {"power": 4, "distortion": 0.2, "thickness": 0.5}}},
    "lights": [{"type": "directional", "direction": )") + direction +
                                                              R"(, "translucency_scale": 2}],
    "objects": [{"mesh": "quad.obj", "material": "m"}]})");
  }
}

std::string bench_of(const fs::path& dir) {
  return "bench " + (dir / "back.json").string() + " " + (dir / "side.json").string() +
         " --paths glsl,arbfp --variants default --quick --min-time 0 --max-time 0 ";
}

TEST(BenchJobs, TwoJobsMakeTheReportOneProcessMakes) {
  if (allowed_cores().size() < 2) GTEST_SKIP() << "one core: no job would have a core of its own";
  test::TempDir dir;
  write_two_scenes(dir.path());
  // An added variant (arbfp's pow=exact, not its default) reaches the jobs with the parent's
  // arguments and makes the same rows.
  const std::string bench = bench_of(dir.path()) + "--add-variant arbfp:pow=exact ";
  const auto one = test::run_ltrender(bench + "-o " + (dir / "one").string());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto two = test::run_ltrender(bench + "--jobs 2 -o " + (dir / "two").string());
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const auto a = nlohmann::json::parse(test::read_file(dir / "one" / "report.json"));
  const auto b = nlohmann::json::parse(test::read_file(dir / "two" / "report.json"));
  EXPECT_EQ(b["pinning"].get<std::string>().rfind("2 jobs (bench --jobs)", 0), 0u) << b["pinning"];
  // Each job pinned to its own core: one CPU worker and llvmpipe in the calling thread, as one
  // pinned process has.
  EXPECT_EQ(b["cpu_threads"], a["cpu_threads"]);
  EXPECT_EQ(b["llvmpipe_threads"], a["llvmpipe_threads"]);
  ASSERT_EQ(a["rows"].size(), b["rows"].size());
  ASSERT_EQ(a["rows"].size(), 2u * 3u);  // glsl, arbfp and arbfp pow=exact on each scene
  for (std::size_t i = 0; i < a["rows"].size(); ++i) {
    const auto& ra = a["rows"][i];
    const auto& rb = b["rows"][i];
    const std::string what = ra["scene"].get<std::string>() + " " + ra["path"].get<std::string>();
    EXPECT_EQ(ra["scene"], rb["scene"]) << i;
    EXPECT_EQ(ra["path"], rb["path"]) << i;
    EXPECT_EQ(ra["variant"], rb["variant"]) << i;
    EXPECT_EQ(ra["cost"], rb["cost"]) << what;
    EXPECT_EQ(ra["work"], rb["work"]) << what;
    if (ra.contains("error")) EXPECT_EQ(ra["error"], rb["error"]) << what;
    const std::string image = test::read_file(dir / "two" / rb["image"].get<std::string>());
    EXPECT_FALSE(image.empty()) << what;
    EXPECT_EQ(test::read_file(dir / "one" / ra["image"].get<std::string>()), image) << what;
  }
  // The two scenes' rows are not the same rows twice: arbfp's error differs between them.
  std::vector<nlohmann::json> arbfp_errors;
  for (const auto& row : b["rows"])
    if (row["path"] == "arbfp" && row["variant"] == "pow=mul") arbfp_errors.push_back(row["error"]);
  ASSERT_EQ(arbfp_errors.size(), 2u);
  EXPECT_NE(arbfp_errors[0], arbfp_errors[1]);
  // The whole report is there, and nothing of the jobs' own is left.
  for (const char* f : {"report.md", "report.csv", "index.html", "contact.png", "chart.svg"})
    EXPECT_TRUE(fs::exists(dir / "two" / f)) << f;
  EXPECT_FALSE(fs::exists(dir / "two" / ".jobs"));
}

// A job needs a core of its own: more jobs than cores, or --pin-core naming one core, is an
// input error naming the option, with nothing written; --pin-core none runs them unpinned.
TEST(BenchJobs, EachJobNeedsACoreOfItsOwnOrPinCoreNone) {
  test::TempDir dir;
  write_two_scenes(dir.path());
  const std::string bench = bench_of(dir.path()) + "--quiet ";
  const auto many = test::run_ltrender(bench + "--jobs 64 -o " + (dir / "bad").string());
  EXPECT_EQ(many.exit_code, 2);
  EXPECT_NE(many.err.find("ltrender: error: --jobs"), std::string::npos) << many.err;
  EXPECT_EQ(std::count(many.err.begin(), many.err.end(), '\n'), 1) << many.err;
  const auto one_core =
      test::run_ltrender(bench + "--jobs 2 --pin-core 0 -o " + (dir / "bad").string());
  EXPECT_EQ(one_core.exit_code, 2);
  EXPECT_NE(one_core.err.find("ltrender: error: --pin-core"), std::string::npos) << one_core.err;
  EXPECT_FALSE(fs::exists(dir / "bad"));
  const auto free =
      test::run_ltrender(bench + "--jobs 3 --pin-core none -o " + (dir / "free").string());
  ASSERT_EQ(free.exit_code, 0) << free.err;
  const auto j = nlohmann::json::parse(test::read_file(dir / "free" / "report.json"));
  EXPECT_EQ(j["pinning"], "3 jobs (bench --jobs), a scene at a time each, not pinned");
  EXPECT_EQ(j["rows"].size(), 4u);
}

// A bad scene is found before any job starts: one line naming it, nothing written.
TEST(BenchJobs, ABadSceneStopsTheBenchBeforeAnyJob) {
  test::TempDir dir;
  write_two_scenes(dir.path());
  test::write_file(dir / "bad.json", "{\"image\": {\"width\": 0}}");
  const auto r = test::run_ltrender(bench_of(dir.path()) + (dir / "bad.json").string() +
                                    " --jobs 2 --pin-core none -o " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.json:image.width"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
}

}  // namespace
}  // namespace lt
