// `ltrender regress` with its cases in worker processes: a case that really aborts or really hangs
// in its worker (the test hook of regress/test_hook.h) fails alone, as `crashed` or `timed out`,
// and every other case keeps its result; the JUnit and the JSON are valid while the run goes on;
// the warn tier between pass and fail.
#include <gtest/gtest.h>

#include <OpenImageIO/detail/pugixml/pugixml.hpp>
#include <chrono>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/build_paths.h"
#include "core/child_process.h"
#include "regress/regress.h"
#include "regress/test_hook.h"
#include "regress_fixture.h"
#include "test_util.h"

namespace lt {
namespace {

// Two quad scenes through reference and glsl: four cases, in this order.
constexpr const char* kIsolationCases[] = {"quad_a/reference/exact", "quad_a/glsl/pow=exact",
                                           "quad_b/reference/exact", "quad_b/glsl/pow=exact"};

// The test hook set for what a test runs, and unset after it.
class HookScope {
 public:
  explicit HookScope(const std::string& value) {
    ::setenv(kRegressTestHookVariable, value.c_str(), 1);
  }
  ~HookScope() { ::unsetenv(kRegressTestHookVariable); }
};

class RegressIsolation : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(test::write_two_quads_with_goldens(dir.path(), "reference,glsl"), 4u);
  }
  std::string command() const {
    return "regress " + (dir / "quad_a.json").string() + " " + (dir / "quad_b.json").string() +
           " --goldens " + (dir / "goldens").string() + " --paths reference,glsl --junit " +
           (dir / "junit.xml").string() + " --json " + (dir / "run.json").string();
  }
  nlohmann::json read_json() const {
    return nlohmann::json::parse(test::read_file(dir / "run.json"));
  }
  test::TempDir dir;
};

// The JUnit's testcases by id ("scene/path:variant" as JUnit names them, turned back to ours).
std::map<std::string, OIIO::pugi::xml_node> junit_cases(const OIIO::pugi::xml_document& doc) {
  std::map<std::string, OIIO::pugi::xml_node> out;
  for (auto suite : doc.child("testsuites").children("testsuite")) {
    for (auto tc : suite.children("testcase")) {
      std::string name = tc.attribute("name").value();
      name[name.find(':')] = '/';
      out[std::string(suite.attribute("name").value()) + "/" + name] = tc;
    }
  }
  return out;
}

TEST_F(RegressIsolation, ACrashAndAHangFailTheirCasesAndTheRunGoesOn) {
  const HookScope hook(std::string("abort@") + kIsolationCases[1] + ";hang@" + kIsolationCases[2]);
  const auto start = std::chrono::steady_clock::now();
  // 4 s, not 1: a case's deadline also covers the render session (its GL context) that the first
  // case of a worker's batch makes, which took over 1 s on a loaded 2-core machine, so the case
  // after the crash timed out too.
  const auto cli = test::run_ltrender(command() + " --case-timeout 4", {60, 0});
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(cli.exit_code, 1) << cli.out << cli.err;
  EXPECT_LT(took, 30.0) << "the hang was not stopped at its deadline";
  EXPECT_NE(cli.out.find(std::string("CRASHED ") + kIsolationCases[1] +
                         ": its worker process was killed by signal 6"),
            std::string::npos)
      << cli.out;
  EXPECT_NE(cli.out.find(std::string("TIMED OUT ") + kIsolationCases[2] +
                         ": took longer than --case-timeout 4 s"),
            std::string::npos)
      << cli.out;
  EXPECT_NE(cli.out.find("2 pass"), std::string::npos) << cli.out;

  OIIO::pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "junit.xml").c_str()));
  EXPECT_EQ(doc.child("testsuites").attribute("tests").as_int(), 4);
  EXPECT_EQ(doc.child("testsuites").attribute("errors").as_int(), 2);
  EXPECT_EQ(doc.child("testsuites").attribute("failures").as_int(), 0);
  const auto cases = junit_cases(doc);
  ASSERT_EQ(cases.size(), 4u);
  EXPECT_STREQ(cases.at(kIsolationCases[1]).child("error").attribute("type").value(), "crashed");
  EXPECT_STREQ(cases.at(kIsolationCases[2]).child("error").attribute("type").value(), "timed out");
  for (const char* id : {kIsolationCases[0], kIsolationCases[3]}) {
    EXPECT_FALSE(cases.at(id).child("error")) << id;
    EXPECT_FALSE(cases.at(id).child("failure")) << id;
  }
  const auto j = read_json();
  EXPECT_EQ(j["complete"], true);
  EXPECT_EQ(j["counts"]["crashed"], 1);
  EXPECT_EQ(j["counts"]["timed out"], 1);
  EXPECT_EQ(j["counts"]["pass"], 2);
  // The cases after the crash and the hang ran and kept their figures.
  EXPECT_EQ(j["cases"][3]["status"], "pass");
  EXPECT_EQ(j["cases"][3]["comparison"]["image"]["max_lsb"], 0.0);
}

// The JUnit and the JSON hold every finished case while the run still goes on: the last case
// hangs (no deadline), the files are read while it does, and the run is then killed.
TEST_F(RegressIsolation, TheOutputsAreValidWhileTheRunGoesOn) {
  const HookScope hook(std::string("hang@") + kIsolationCases[3]);
  std::vector<std::string> args;
  std::stringstream words(command());
  for (std::string w; words >> w;) args.push_back(w);
  ChildProcess run({build_paths::ltrender_binary(), args, {}, dir / "log.txt"});
  nlohmann::json j;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (std::chrono::steady_clock::now() < deadline) {
    if (fs::exists(dir / "run.json")) {
      j = read_json();  // written atomically: whenever it exists, it parses
      if (j["cases"].size() == 3) break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(j["cases"].size(), 3u) << test::read_file(dir / "log.txt");
  EXPECT_EQ(j["complete"], false);
  EXPECT_EQ(j["shard_cases"], 4);
  OIIO::pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "junit.xml").c_str()));
  EXPECT_EQ(junit_cases(doc).size(), 3u);
  EXPECT_FALSE(run.wait_until(ChildProcess::Clock::now())) << "the run ended; it should hang";
  run.stop(SIGTERM, std::chrono::milliseconds(1000));
}

// idiff's warn tier: within the fail bounds but not identical passes as "warn" (exit 0), and
// the scene's block sets where it starts.
TEST_F(RegressIsolation, ACaseWithinToleranceThatMovedWarns) {
  test::push_pixel(dir / "goldens" / "quad_a__glsl.png", 20, 15, 2);  // under the 3 LSB limit
  const auto cli = test::run_ltrender(command());
  EXPECT_EQ(cli.exit_code, 0) << cli.out << cli.err;
  EXPECT_NE(cli.out.find(std::string("warn    ") + kIsolationCases[1] + ": "), std::string::npos)
      << cli.out;
  EXPECT_NE(cli.out.find("; warn: 0.0651042% of image pixels (1 of 1536) have error > 0 LSB"),
            std::string::npos)
      << cli.out;
  const auto j = read_json();
  EXPECT_EQ(j["counts"]["warn"], 1);
  EXPECT_EQ(j["cases"][1]["status"], "warn");
  EXPECT_EQ(j["cases"][1]["failed"], false);
  OIIO::pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir / "junit.xml").c_str()));
  EXPECT_NE(std::string(junit_cases(doc).at(kIsolationCases[1]).child("system-out").text().get())
                .find("warn: "),
            std::string::npos);
  // A warn threshold of 2 LSB in the scene: the same 2 LSB pass plainly.
  test::write_quad_scene(dir.path(), "quad_a", 4,
                         R"("regress": {"hard_warn_lsb": 2, "warn_lsb": 2})");
  const auto quiet = test::run_ltrender(command());
  EXPECT_EQ(read_json()["cases"][1]["status"], "pass") << quiet.out;
}

TEST_F(RegressIsolation, BadJobsOrDeadlineIsOneErrorLine) {
  for (const std::string bad : {"--jobs -1", "--case-timeout -2", "--case-timeout soon"}) {
    const auto cli = test::run_ltrender(command() + " " + bad);
    EXPECT_EQ(cli.exit_code, 2) << bad;
    EXPECT_NE(cli.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << cli.err;
    EXPECT_FALSE(fs::exists(dir / "junit.xml")) << bad;
  }
}

}  // namespace
}  // namespace lt
