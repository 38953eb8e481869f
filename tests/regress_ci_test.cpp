// `ltrender regress` where CI shows it (docs/regress.md "In CI"): GitHub Actions' workflow
// commands and step summary, GitLab's JUnit attachments, --artifacts failures, and `regress
// merge` giving the merged run the same annotations and attachments as the unsharded run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>

#include "regress/github_actions.h"
#include "regress/golden_key.h"
#include "regress/regress.h"
#include "regress_fixture.h"
#include "test_util.h"

namespace lt {
namespace {

// Two quad scenes through three paths (six cases); glsl on quad_b fails (one pixel of its golden
// 9 LSB off, a shading change: no neighbour holds it) and reference on quad_a warns (1 LSB).
// The command runs in the scenes' folder, as a CI job runs in the project's.
class RegressCi : public ::testing::Test {
 protected:
  void SetUp() override {
    ASSERT_EQ(test::write_two_quads_with_goldens(dir.path(), "reference,glsl,combiners"), 6u);
    test::push_pixel(dir / "goldens" / "quad_b__glsl.png", 20, 15, 9);
    test::push_pixel(dir / "goldens" / "quad_a__reference.png", 10, 10, 1);
    cwd = fs::current_path();
    fs::current_path(dir.path());
    summary = dir / "summary.md";
    test::write_file(summary, "earlier step\n");
    setenv("GITHUB_ACTIONS", "true", 1);
    setenv("GITHUB_STEP_SUMMARY", summary.c_str(), 1);
  }
  void TearDown() override {
    unsetenv("GITHUB_ACTIONS");
    unsetenv("GITHUB_STEP_SUMMARY");
    fs::current_path(cwd);
  }
  static std::string run_args() {
    return "regress quad_a.json quad_b.json --goldens goldens --paths reference,glsl,combiners "
           "--quiet --jobs 0";
  }
  // The lines of `text` that are workflow commands.
  static std::vector<std::string> commands(const std::string& text) {
    std::vector<std::string> lines;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);) {
      if (line.rfind("::", 0) == 0) lines.push_back(line);
    }
    return lines;
  }
  // The message of case `id` in a --json file.
  static std::string message(const fs::path& json_file, const std::string& id) {
    const auto run = nlohmann::json::parse(test::read_file(json_file));
    for (const auto& c : run.at("cases")) {
      if (c.at("id") == id) return c.at("message").get<std::string>();
    }
    ADD_FAILURE() << "no case " << id;
    return "";
  }
  test::TempDir dir;
  fs::path summary, cwd;
};

TEST(GitHubEscape, DataAndPropertiesAsTheWorkflowCommandsDocSays) {
  EXPECT_EQ(github_escape_data("50% a\r\nb: c, d"), "50%25 a%0D%0Ab: c, d");
  EXPECT_EQ(github_escape_property("50% a\r\nb: c, d"), "50%25 a%0D%0Ab%3A c%2C d");
}

TEST_F(RegressCi, AnnotationsSummaryAttachmentsAndOnlyTheFailuresImages) {
  const auto r = test::run_ltrender(run_args() +
                                    " --json run.json --junit junit.xml -o report --artifacts "
                                    "failures");
  ASSERT_EQ(r.exit_code, 1) << r.out << r.err;
  const std::string fail_id = "quad_b/glsl/pow=exact";
  const std::string warn_id =
      "quad_a/reference/" + nlohmann::json::parse(test::read_file(dir / "run.json"))
                                .at("cases")[0]
                                .at("variant")
                                .get<std::string>();
  const std::string fail_message = message(dir / "run.json", fail_id);
  EXPECT_NE(fail_message.find("max 9.000 LSB at 20,15"), std::string::npos) << fail_message;
  // One command per failing or warned case, in the cases' order (quad_a's before quad_b's), the
  // scene file as given, the case as its title, the message with its '%' as %25 (the messages
  // hold no line break, the ids no ':' or ',').
  const auto percent_escaped = [](const std::string& text) {
    return std::regex_replace(text, std::regex("%"), "%25");
  };
  ASSERT_NE(fail_message.find('%'), std::string::npos);
  EXPECT_EQ(commands(r.out),
            (std::vector<std::string>{"::warning file=quad_a.json,title=" + warn_id + "::" +
                                          percent_escaped(message(dir / "run.json", warn_id)),
                                      "::error file=quad_b.json,title=" + fail_id +
                                          "::" + percent_escaped(fail_message)}));

  // Appended after the earlier step's line: the counts, then the two cases' figures.
  const std::string text = test::read_file(summary);
  EXPECT_EQ(text.rfind("earlier step\n### ltrender regress\n\n"
                       "| cases | pass | warn | fail | skipped |\n|---:|---:|---:|---:|---:|\n"
                       "| 6 | 4 | 1 | 1 | 0 |\n\n",
                       0),
            0u)
      << text;
  EXPECT_NE(text.find("\n| " + fail_id + " | fail | 9.00 | 0 | 1 | 9.00 | "), std::string::npos)
      << text;
  EXPECT_NE(text.find("\n| " + warn_id + " | warn | 1.00 | "), std::string::npos) << text;

  // GitLab's attachments: the failing case's render, golden and heatmap, from the project folder.
  const std::string junit = test::read_file(dir / "junit.xml");
  EXPECT_NE(junit.find("<system-out>[[ATTACHMENT|report/images/quad_b__glsl.png]]\n"
                       "[[ATTACHMENT|report/images/quad_b__glsl__golden.png]]\n"
                       "[[ATTACHMENT|report/images/quad_b__glsl__heatmap.png]]</system-out>"),
            std::string::npos)
      << junit;
  const std::regex attachment(R"(\[\[ATTACHMENT\|([^\]]+)\]\])");
  size_t attachments = 0;
  for (std::sregex_iterator it(junit.begin(), junit.end(), attachment), end; it != end; ++it) {
    ++attachments;
    EXPECT_TRUE(fs::is_regular_file(dir / (*it)[1].str())) << (*it)[1];
  }
  EXPECT_EQ(attachments, 6u);  // the failing and the warned case, three images each

  // --artifacts failures: the images of those two cases, none of the four that pass.
  std::set<std::string> images;
  for (const auto& e : fs::directory_iterator(dir / "report" / "images"))
    images.insert(e.path().filename().string());
  EXPECT_EQ(images,
            (std::set<std::string>{"quad_a__reference.png", "quad_a__reference__golden.png",
                                   "quad_a__reference__heatmap.png", "quad_b__glsl.png",
                                   "quad_b__glsl__golden.png", "quad_b__glsl__heatmap.png"}));
}

TEST_F(RegressCi, MergeAnnotatesAndAttachesAsTheUnshardedRun) {
  const auto whole =
      test::run_ltrender(run_args() + " --json whole.json --junit whole.xml -o whole");
  ASSERT_EQ(whole.exit_code, 1) << whole.err;
  // The shards, as examples/ci/ runs them (each JSON beside its page's folder), in this process:
  // the command's records are the same (RegressMerge and RegressIsolation check it).
  for (int i = 1; i <= 2; ++i) {
    RegressOptions o;
    o.inputs = {"quad_a.json", "quad_b.json"};
    o.goldens = "goldens";
    o.golden_key = renderer_golden_key();
    o.paths = "reference,glsl,combiners";
    o.quiet = true;
    o.shard = Shard{i, 2};
    o.json_file = "s" + std::to_string(i) + ".json";
    o.report_dir = "s" + std::to_string(i);
    write_regress_outputs(o, run_regress(o));
  }
  const std::string before_merge = test::read_file(summary);
  const auto merged =
      test::run_ltrender("regress merge s1.json s2.json --ci github --junit merged.xml -o merged");
  ASSERT_EQ(merged.exit_code, 1) << merged.err;
  EXPECT_EQ(commands(merged.out), commands(whole.out));
  EXPECT_EQ(commands(merged.out).size(), 2u);
  // The merged summary appended is the unsharded one, the run's time aside.
  const std::regex seconds(" in [0-9.]+ s\n$");
  const std::string text = test::read_file(summary);
  const std::string whole_summary = before_merge.substr(std::string("earlier step\n").size());
  EXPECT_EQ(std::regex_replace(text.substr(before_merge.size()), seconds, ""),
            std::regex_replace(whole_summary, seconds, ""));
  // The same attachments, in the merged page's folder, each a file there.
  const std::string junit = test::read_file(dir / "merged.xml");
  const std::regex attachment(R"(\[\[ATTACHMENT\|([^\]]+)\]\])");
  std::vector<std::string> paths;
  for (std::sregex_iterator it(junit.begin(), junit.end(), attachment), end; it != end; ++it) {
    paths.push_back((*it)[1].str());
    EXPECT_TRUE(fs::is_regular_file(dir / paths.back())) << paths.back();
  }
  const std::string whole_junit = test::read_file(dir / "whole.xml");
  std::vector<std::string> whole_paths;
  for (std::sregex_iterator it(whole_junit.begin(), whole_junit.end(), attachment), end; it != end;
       ++it)
    whole_paths.push_back(std::regex_replace((*it)[1].str(), std::regex("^whole/"), "merged/"));
  EXPECT_EQ(paths, whole_paths);
  EXPECT_EQ(paths.size(), 6u);
}

// Refused before any scene is read or any golden looked for: one line, exit 2, nothing written.
TEST(RegressCiOptions, ABadArtifactsOrCiValueIsOneLine) {
  test::TempDir dir;
  test::write_quad_scene(dir.path(), "quad_a", 4);
  for (const std::string& bad : {" --artifacts some", " --ci jenkins"}) {
    const auto r = test::run_ltrender("regress " + (dir / "quad_a.json").string() + " --goldens " +
                                      (dir / "goldens").string() + bad + " --json " +
                                      (dir / "bad.json").string());
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_EQ(r.err.rfind("ltrender: error: --", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "bad.json"));
  }
}

}  // namespace
}  // namespace lt
