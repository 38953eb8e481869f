// `ltrender regress merge`: the shards of one run made one review, identical (times aside) to
// the run without shards, for N = 4 and N = 1; a missing, a duplicated and another run's shard
// refused by name with nothing written; a platform label in the JUnit's class names.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <regex>

#include "core/file_name.h"
#include "regress/regress.h"
#include "regress_fixture.h"
#include "test_util.h"

namespace lt {
namespace {

// Every time a run measures, replaced: what "identical, times aside" leaves out.
std::string without_times(const std::string& text) {
  static const std::regex json_seconds("\"seconds\": [-0-9.e+]+");
  static const std::regex xml_time("time=\"[0-9.]+\"");
  static const std::regex page_time("[0-9]+\\.[0-9]+ s\\b");
  std::string s = std::regex_replace(text, json_seconds, "\"seconds\": T");
  s = std::regex_replace(s, xml_time, "time=\"T\"");
  return std::regex_replace(s, page_time, "T s");
}

// `text` with the output folder `out` written as OUT.
std::string in_folder(std::string text, const fs::path& out) {
  const std::string from = out.string() + "/";
  for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
    text.replace(at, from.size(), "OUT/");
  return text;
}

class RegressMerge : public ::testing::Test {
 protected:
  void SetUp() override {
    test::write_quad_scene(dir.path(), "quad_a", 4);
    test::write_quad_scene(dir.path(), "quad_b", 16);
    RegressOptions o = options();
    o.update = true;
    ASSERT_EQ(run_regress(o).count(CaseStatus::kCreated), 6u);
    // One case fails and one warns, so the outputs hold figures, reasons and a failure.
    test::push_pixel(dir / "goldens" / "quad_b__glsl.png", 20, 15, 9);
    test::push_pixel(dir / "goldens" / "quad_a__reference.png", 10, 10, 1);
  }
  // The run in this process (the library's; the command's workers give the same records, which
  // the isolation tests check): what a shard's --json and page are made from.
  RegressOptions options(const std::string& paths = "reference,glsl,combiners") const {
    RegressOptions o;
    o.inputs = {dir / "quad_a.json", dir / "quad_b.json"};
    o.goldens = dir / "goldens";
    o.paths = paths;
    o.quiet = true;
    return o;
  }
  void run_into(RegressOptions o, const fs::path& out) const {
    fs::create_directories(out);
    o.json_file = out / "run.json";
    o.junit_file = out / "junit.xml";
    o.report_dir = out / "report";
    write_regress_outputs(o, run_regress(o));
  }
  std::string run_args(const std::string& paths = "reference,glsl,combiners") const {
    return "regress " + (dir / "quad_a.json").string() + " " + (dir / "quad_b.json").string() +
           " --goldens " + (dir / "goldens").string() + " --paths " + paths;
  }
  void expect_same_outputs(const fs::path& a, const fs::path& b) const {
    for (const char* f : {"run.json", "junit.xml", "report/index.html"}) {
      // The JUnit's attachments name each run's own report folder.
      EXPECT_EQ(without_times(in_folder(test::read_file(a / f), a)),
                without_times(in_folder(test::read_file(b / f), b)))
          << f;
    }
    size_t images = 0;
    for (const auto& e : fs::directory_iterator(a / "report" / "images")) {
      ++images;
      const fs::path other = b / "report" / "images" / e.path().filename();
      ASSERT_TRUE(fs::exists(other)) << other;
      EXPECT_EQ(test::read_file(e.path()), test::read_file(other)) << other;
    }
    EXPECT_EQ(images, 18u);  // 6 cases: render, golden, heatmap
  }
  // Runs the shards of N and returns their JSON files.
  std::string shards(int n, const std::string& paths = "reference,glsl,combiners") const {
    std::string files;
    for (int i = 1; i <= n; ++i) {
      const fs::path out =
          dir / ("shards" + std::to_string(n) + "_" + file_name_safe(paths)) / std::to_string(i);
      RegressOptions o = options(paths);
      o.shard = Shard{i, n};
      run_into(o, out);
      files += " " + (out / "run.json").string();
    }
    return files;
  }
  test::TempDir dir;
};

TEST_F(RegressMerge, FourShardsOrOneMergeIntoTheUnshardedRun) {
  run_into(options(), dir / "whole");
  for (int n : {4, 1}) {
    const fs::path merged = dir / ("merged" + std::to_string(n));
    fs::create_directories(merged);
    const auto m = test::run_ltrender(
        "regress merge" + shards(n) + " --json " + (merged / "run.json").string() + " --junit " +
        (merged / "junit.xml").string() + " -o " + (merged / "report").string());
    EXPECT_EQ(m.exit_code, 1) << m.out << m.err;  // the failing case fails the merge too
    expect_same_outputs(dir / "whole", merged);
  }
}

TEST_F(RegressMerge, AMissingDuplicatedOrForeignShardIsRefusedByName) {
  const std::string four = shards(4);
  std::vector<std::string> files;
  std::stringstream words(four);
  for (std::string w; words >> w;) files.push_back(w);
  const std::string one = shards(1);
  const std::string foreign = shards(4, "reference,glsl");
  std::vector<std::string> foreign_files;
  std::stringstream fw(foreign);
  for (std::string w; fw >> w;) foreign_files.push_back(w);

  const fs::path out = dir / "merged";
  const std::string outs =
      " --json " + (out / "run.json").string() + " -o " + (out / "report").string();
  fs::create_directories(out);
  struct Bad {
    std::string shards, error;
  };
  for (const Bad& bad : std::vector<Bad>{
           {files[0] + " " + files[1] + " " + files[3],
            "SHARD.json: shard 3/4 is missing (3 of 4 given)"},
           {four + " " + files[1], files[1] + ":shard: shard 2/4 twice (also " + files[1] + ")"},
           {one + one, one.substr(1) + ":shard: shard 1/1 twice (also " + one.substr(1) + ")"},
           {files[0] + " " + files[1] + " " + foreign_files[2] + " " + files[3],
            foreign_files[2] + ":run: another run's shard: its run differs from " + files[0] +
                "'s"},
       }) {
    const auto r = test::run_ltrender("regress merge " + bad.shards + outs);
    EXPECT_EQ(r.exit_code, 2) << bad.shards << "\n" << r.out;
    EXPECT_EQ(r.err, "ltrender: error: " + bad.error + "\n");
    EXPECT_FALSE(fs::exists(out / "run.json"));
    EXPECT_FALSE(fs::exists(out / "report"));
  }
  // A scene file is no shard.
  const auto scene = test::run_ltrender("regress merge " + (dir / "quad_a.json").string() + outs);
  EXPECT_EQ(scene.exit_code, 2);
  EXPECT_NE(scene.err.find("not the --json of an ltrender regress run"), std::string::npos)
      << scene.err;
}

TEST_F(RegressMerge, ALabelKeepsAPlatformsCasesApart) {
  const fs::path out = dir / "labelled";
  fs::create_directories(out);
  const auto r = test::run_ltrender(run_args("glsl") + " --label softpipe-ci --junit " +
                                    (out / "junit.xml").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  const std::string junit = test::read_file(out / "junit.xml");
  EXPECT_NE(
      junit.find("<testcase classname=\"regress.softpipe-ci.quad_b\" name=\"glsl:pow=exact\""),
      std::string::npos)
      << junit;
  EXPECT_NE(junit.find("<testsuite name=\"softpipe-ci/quad_a\""), std::string::npos) << junit;
  for (const std::string bad : {"a/b", "two words", ".."}) {
    const auto refused = test::run_ltrender(run_args("glsl") + " --label '" + bad + "'");
    EXPECT_EQ(refused.exit_code, 2) << bad;
    EXPECT_NE(refused.err.find("ltrender: error: --label:" + bad + ": may hold only"),
              std::string::npos)
        << refused.err;
  }
}

}  // namespace
}  // namespace lt
