// `ltrender regress` on small real renders: pass, fail, missing golden, the update round trip,
// bad input among good scenes, the shard partition, JUnit XML read back with a real parser, the
// scene's "regress" block, and the report page's figures.
#include "regress/regress.h"

#include <gtest/gtest.h>

#include <OpenImageIO/detail/pugixml/pugixml.hpp>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/fs.h"
#include "map_test_util.h"
#include "regress/junit.h"
#include "regress_fixture.h"
#include "test_util.h"

namespace lt {
namespace {

// Two quad scenes through three paths: six cases, each a real OSMesa render at 48x32.
class Regress : public ::testing::Test {
 protected:
  void SetUp() override {
    test::write_quad_scene(dir.path(), "quad_a", 4);
    test::write_quad_scene(dir.path(), "quad_b", 16);
  }
  RegressOptions options(bool update = false) const {
    RegressOptions o;
    o.inputs = {dir.path() / "quad_a.json", dir.path() / "quad_b.json"};
    o.goldens = dir / "goldens";
    o.paths = "reference,glsl,combiners";
    o.update = update;
    o.quiet = true;
    return o;
  }
  const CaseResult& find(const RegressRun& run, const std::string& id) const {
    for (const CaseResult& r : run.results) {
      if (r.regress_case.id() == id) return r;
    }
    ADD_FAILURE() << "no case " << id;
    return run.results.front();
  }
  test::TempDir dir;
};

TEST_F(Regress, PassesAgainstTheGoldensItWrote) {
  const RegressRun created = run_regress(options(true));
  ASSERT_EQ(created.results.size(), 6u);
  EXPECT_EQ(created.count(CaseStatus::kCreated), 6u);
  EXPECT_TRUE(fs::exists(dir / "goldens" / "quad_a__glsl.png"));
  const RegressRun run = run_regress(options());
  EXPECT_EQ(run.count(CaseStatus::kPass), 6u);
  EXPECT_FALSE(run.failed());
  for (const CaseResult& r : run.results) {
    ASSERT_TRUE(r.figures) << r.regress_case.id();
    // The same render, bit for bit, against the golden's bytes: no error at all (a float's
    // k/255 used to leave up to 8e-6 LSB).
    EXPECT_EQ(r.figures->max_lsb, 0.0) << r.regress_case.id();
    EXPECT_EQ(r.figures->max_x, -1) << r.regress_case.id();
  }
  const auto cli = test::run_ltrender(
      "regress " + (dir / "quad_a.json").string() + " " + (dir / "quad_b.json").string() +
      " --goldens " + (dir / "goldens").string() + " --paths reference,glsl,combiners");
  EXPECT_EQ(cli.exit_code, 0) << cli.out << cli.err;
  EXPECT_NE(cli.out.find("6 pass"), std::string::npos) << cli.out;

  // The JUnit and JSON files may go into the report directory -o creates.
  const fs::path report = dir / "new_report";
  const auto into_report = test::run_ltrender(
      "regress " + (dir / "quad_a.json").string() + " --goldens " + (dir / "goldens").string() +
      " --paths reference -o " + report.string() + " --junit " + (report / "junit.xml").string() +
      " --json " + (report / "regress.json").string());
  EXPECT_EQ(into_report.exit_code, 0) << into_report.err;
  EXPECT_TRUE(fs::exists(report / "junit.xml"));
  EXPECT_TRUE(fs::exists(report / "regress.json"));
  EXPECT_TRUE(fs::exists(report / "index.html"));
}

TEST_F(Regress, OnePixelOverTheHardLimitFails) {
  run_regress(options(true));
  // 4 LSB on one pixel: under 0.5 % of the 1536 pixels, but over the 3 LSB hard limit.
  test::push_pixel(dir / "goldens" / "quad_b__glsl.png", 20, 15, 4);
  const RegressRun run = run_regress(options());
  EXPECT_TRUE(run.failed());
  EXPECT_EQ(run.count(CaseStatus::kFail), 1u);
  const CaseResult& r = find(run, "quad_b/glsl/pow=exact");
  EXPECT_EQ(r.status, CaseStatus::kFail);
  EXPECT_NEAR(r.figures->max_lsb, 4.0, 1e-4);
  EXPECT_EQ(r.figures->max_x, 20);
  EXPECT_EQ(r.figures->max_y, 15);
  EXPECT_EQ(r.verdict.hard_failing_pixels, 1u);
  EXPECT_NE(r.message.find("1 image pixels have error > 3 LSB"), std::string::npos) << r.message;
  // Under the limit passes, in the warn tier (it differs): 2 LSB on one pixel.
  test::push_pixel(dir / "goldens" / "quad_a__glsl.png", 20, 15, 2);
  EXPECT_EQ(find(run_regress(options()), "quad_a/glsl/pow=exact").status, CaseStatus::kWarn);

  const auto cli = test::run_ltrender("regress " + dir.path().string() + " --goldens " +
                                      (dir / "goldens").string() + " --paths glsl");
  EXPECT_EQ(cli.exit_code, 1) << cli.out << cli.err;
  // The max is stated once, by the reason that fails the case.
  EXPECT_NE(cli.out.find("FAIL    quad_b/glsl/pow=exact: mean "), std::string::npos) << cli.out;
  EXPECT_NE(cli.out.find("(max 4.000 LSB at 20,15 R)"), std::string::npos) << cli.out;
}

TEST_F(Regress, MissingGoldenFailsWithTheCommandThatCreatesIt) {
  run_regress(options(true));
  fs::remove(dir / "goldens" / "quad_a__combiners.png");
  const RegressRun run = run_regress(options());
  const CaseResult& r = find(run, "quad_a/combiners/t=vertex");
  EXPECT_EQ(r.status, CaseStatus::kMissing);
  EXPECT_TRUE(run.failed());
  const std::string command = update_command(options(), r.regress_case, dir / "quad_a.json");
  EXPECT_NE(r.message.find(command), std::string::npos) << r.message;
  // The command, as printed, creates exactly that golden.
  const auto made = test::run_ltrender(command.substr(std::string("ltrender ").size()));
  EXPECT_EQ(made.exit_code, 0) << made.out << made.err;
  EXPECT_NE(made.out.find("created quad_a/combiners/t=vertex"), std::string::npos) << made.out;
  EXPECT_FALSE(run_regress(options()).failed());
}

TEST_F(Regress, UpdateRewritesOnlyWhatMovedAndListsIt) {
  run_regress(options(true));
  const fs::path moved = dir / "goldens" / "quad_a__reference.png";
  const fs::path steady = dir / "goldens" / "quad_b__reference.png";
  test::push_pixel(moved, 10, 10, 40);
  const auto steady_time = fs::last_write_time(steady);
  const RegressRun update = run_regress(options(true));
  EXPECT_EQ(update.count(CaseStatus::kUpdated), 1u);
  EXPECT_EQ(update.count(CaseStatus::kKept), 5u);
  EXPECT_EQ(find(update, "quad_a/reference/exact").status, CaseStatus::kUpdated);
  EXPECT_EQ(fs::last_write_time(steady), steady_time);  // within tolerance: left as it was
  EXPECT_FALSE(run_regress(options()).failed());
  // No temporaries are left beside the goldens.
  for (const auto& e : fs::directory_iterator(dir / "goldens"))
    EXPECT_EQ(e.path().filename().string().find(kPartialOutputTag), std::string::npos) << e.path();

  test::push_pixel(moved, 10, 10, 40);
  const auto cli = test::run_ltrender("regress " + dir.path().string() + " --goldens " +
                                      (dir / "goldens").string() +
                                      " --paths reference,glsl,combiners --update --quiet "
                                      "--golden-key none");
  EXPECT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_NE(cli.out.find("updated quad_a/reference/exact: mean "), std::string::npos) << cli.out;
  EXPECT_NE(cli.out.find("(max 40.000 LSB at 10,10 R)"), std::string::npos) << cli.out;
  EXPECT_EQ(cli.out.find("\nkept"), std::string::npos) << "--quiet lists only what changed";
  EXPECT_NE(cli.out.find("5 kept"), std::string::npos) << cli.out;
}

TEST_F(Regress, BadSceneAmongGoodOnesWritesNothing) {
  fs::create_directories(dir / "bad");
  test::write_file(dir / "bad" / "bad.json", "{\"image\": {\"width\": 0}}");
  const auto cli = test::run_ltrender(
      "regress " + (dir / "quad_a.json").string() + " " + (dir / "bad").string() + " " +
      (dir / "quad_b.json").string() + " --goldens " + (dir / "goldens").string() +
      " --update --junit " + (dir / "j.xml").string() + " --json " + (dir / "r.json").string() +
      " -o " + (dir / "report").string());
  EXPECT_EQ(cli.exit_code, 2);
  EXPECT_NE(
      cli.err.find("ltrender: error: " + (dir / "bad" / "bad.json").string() + ":image.width"),
      std::string::npos)
      << cli.err;
  EXPECT_EQ(std::count(cli.err.begin(), cli.err.end(), '\n'), 1) << cli.err;
  for (const char* f : {"goldens", "j.xml", "r.json", "report"})
    EXPECT_FALSE(fs::exists(dir / f)) << f;
  // A bad --paths entry and a bad shard are refused the same way.
  for (const std::string& bad : {"--paths glsl:pow=nope", "--paths nope", "--shard 3/2"}) {
    const auto r = test::run_ltrender("regress " + dir.path().string() + " --goldens " +
                                      (dir / "goldens").string() + " --update " + bad);
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_NE(r.err.find(bad.substr(0, bad.find(' '))), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "goldens")) << bad;
  }
}

// Issue 24: a scene one of the paths refuses when it is built (gx: two materials with one C
// name) stopped the run after the other scenes' goldens were written.
TEST_F(Regress, AScenePathRefusesStopsTheRunBeforeAnyGoldenIsWritten) {
  fs::create_directories(dir / "set");
  test::write_quad_scene(dir / "set", "a_good", 4);
  // A lobe ramp over 1 (a float ramp): gx's 8-bit LUT cannot hold it, which gx finds when it
  // builds the path, not when it reads the scene.
  test::write_test_image(dir / "set" / "hot_ramp.exr", 4, 1, 3, std::vector<float>(12, 2.0f));
  test::write_file(dir / "set" / "b_refused.json", R"({
    "image": {"width": 48, "height": 32},
    "camera": {"eye": [0, 0, 3], "target": [0, 0, 0], "fov_y_deg": 40},
    "materials": {"m_1": {"albedo": [0.5, 0.7, 0.6], "translucency": {"power": 4,
                  "distortion": 0.2, "ambient": 0.1, "thickness": 0.5, "ramp": "hot_ramp.exr"}}},
    "lights": [{"type": "directional", "direction": [0.3, 0.2, 1]}],
    "objects": [{"mesh": "quad.obj", "material": "m_1"}]})");
  const auto cli = test::run_ltrender("regress " + (dir / "set").string() + " --goldens " +
                                      (dir / "goldens").string() + " --paths glsl,gx --update");
  EXPECT_EQ(cli.exit_code, 2) << cli.out << cli.err;
  EXPECT_EQ(cli.err, "ltrender: error: " + (dir / "set" / "b_refused.json").string() +
                         ":materials.m_1.translucency.ramp: gx: the ramp holds values up to 2; "
                         "the 8-bit lobe LUT holds 0..1\n");
  EXPECT_EQ(cli.out, "") << "no case ran";
  EXPECT_FALSE(fs::exists(dir / "goldens"));
  // Without the path that refuses it, the scene runs.
  const auto glsl = test::run_ltrender("regress " + (dir / "set").string() + " --goldens " +
                                       (dir / "goldens").string() + " --paths glsl --update");
  EXPECT_EQ(glsl.exit_code, 0) << glsl.err;
  EXPECT_TRUE(fs::exists(dir / "goldens" / "b_refused__glsl.png"));
}

// Issue 24: a --goldens folder that does not exist was reported as every case MISSING.
TEST_F(Regress, AMissingGoldensFolderIsOneErrorUnlessUpdateCreatesIt) {
  const fs::path missing = dir / "no_such_goldens";
  const auto cli = test::run_ltrender("regress " + dir.path().string() + " --goldens " +
                                      missing.string() + " --paths glsl,reference");
  EXPECT_EQ(cli.exit_code, 2) << cli.out << cli.err;
  EXPECT_EQ(cli.err, "ltrender: error: " + missing.string() +
                         ": no such folder of goldens (--update creates it and writes them)\n");
  EXPECT_EQ(cli.out, "");
  EXPECT_FALSE(fs::exists(missing));
  const auto update = test::run_ltrender("regress " + dir.path().string() + " --goldens " +
                                         missing.string() + " --paths glsl --update");
  EXPECT_EQ(update.exit_code, 0) << update.err;
  EXPECT_TRUE(fs::exists(missing / "quad_a__glsl.png"));
  // Issue 24: a created golden's line ended in a dangling colon; it names the file it wrote.
  // Then how it stands against its path's bound (regress_new_golden_test.cpp).
  EXPECT_NE(update.out.find("created quad_a/glsl/pow=exact: wrote " +
                            (missing / "quad_a__glsl.png").string() +
                            "; within glsl:pow=exact's bound to the reference"),
            std::string::npos)
      << update.out;
  std::stringstream lines(update.out);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_NE(line.back(), ':') << line;
    EXPECT_EQ(line.find(": \n"), std::string::npos) << line;
  }
}

// Issue 24: a failing case stated its failing pixels and its max twice (figures, then reasons).
TEST_F(Regress, AFailingCaseStatesEachFigureOnce) {
  run_regress(options(true));
  // quad_b's glsl golden replaced by quad_a's render: another lobe, wrong almost everywhere.
  fs::copy_file(dir / "goldens" / "quad_a__glsl.png", dir / "goldens" / "quad_b__glsl.png",
                fs::copy_options::overwrite_existing);
  const RegressRun run = run_regress(options());
  const CaseResult& r = find(run, "quad_b/glsl/pow=exact");
  ASSERT_EQ(r.status, CaseStatus::kFail);
  ASSERT_EQ(r.verdict.reasons.size(), 2u) << r.message;  // both criteria fail: both reasons
  const std::string count = std::to_string(r.verdict.failing_pixels);
  auto occurrences = [&](const std::string& what) {
    size_t n = 0;
    for (size_t at = r.message.find(what); at != std::string::npos;
         at = r.message.find(what, at + 1))
      ++n;
    return n;
  };
  EXPECT_EQ(occurrences("(" + count + " of "), 1u) << r.message;
  EXPECT_EQ(occurrences(count + " pixels"), 0u) << r.message;
  EXPECT_EQ(occurrences("max "), 1u) << r.message;
  EXPECT_EQ(occurrences("mean "), 1u) << r.message;
  // A passing case keeps every figure in its one line.
  const CaseResult& pass = find(run, "quad_a/glsl/pow=exact");
  EXPECT_EQ(pass.message, "max 0.00 LSB, mean 0.000 LSB, 0 pixels (0.000%) over fail_lsb");
}

TEST_F(Regress, AnOutputNeverOverwritesAnInputAndACaseRunsOnce) {
  const std::string scene = test::read_file(dir / "quad_a.json");
  const auto r =
      test::run_ltrender("regress " + (dir / "quad_a.json").string() + " --goldens " +
                         (dir / "goldens").string() + " --junit " + (dir / "quad_a.json").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("would overwrite an input"), std::string::npos) << r.err;
  EXPECT_EQ(test::read_file(dir / "quad_a.json"), scene);
  RegressOptions o = options(true);
  o.paths = "glsl,glsl:pow=exact,glsl:*";  // pow=exact three times, pow=exact:f32 once
  EXPECT_EQ(run_regress(o).results.size(), 4u);
}

TEST_F(Regress, ShardsPartitionTheCases) {
  run_regress(options(true));
  std::set<std::string> all;
  for (const CaseResult& r : run_regress(options()).results) all.insert(r.regress_case.id());
  ASSERT_EQ(all.size(), 6u);
  for (int n : {1, 2, 4, 7}) {
    std::multiset<std::string> seen;
    size_t smallest = SIZE_MAX, largest = 0;
    for (int i = 1; i <= n; ++i) {
      RegressOptions o = options();
      o.shard = parse_shard(std::to_string(i) + "/" + std::to_string(n));
      const RegressRun run = run_regress(o);
      EXPECT_EQ(run.total_cases, 6u);
      for (const CaseResult& r : run.results) seen.insert(r.regress_case.id());
      smallest = std::min(smallest, run.results.size());
      largest = std::max(largest, run.results.size());
    }
    EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()), all) << n << " shards";
    EXPECT_EQ(seen.size(), all.size()) << n << " shards: a case ran twice";
    EXPECT_LE(largest - smallest, 1u) << n << " shards";
  }
}

TEST_F(Regress, JUnitXmlReadsBackWithTheRunsCounts) {
  RegressOptions o = options(true);
  o.paths = "reference,glsl,combiners,gx:t=texgen";  // gx t=texgen is refused under perspective
  run_regress(o);
  test::push_pixel(dir / "goldens" / "quad_a__glsl.png", 5, 5, 9);
  fs::remove(dir / "goldens" / "quad_b__combiners.png");
  o.update = false;
  o.junit_file = dir / "junit.xml";
  const RegressRun run = run_regress(o);
  write_regress_outputs(o, run);

  OIIO::pugi::xml_document doc;
  const auto parsed = doc.load_file((dir / "junit.xml").c_str());
  ASSERT_TRUE(parsed) << parsed.description();
  const auto suites = doc.child("testsuites");
  ASSERT_TRUE(suites);
  EXPECT_EQ(suites.attribute("tests").as_int(), 8);
  EXPECT_EQ(suites.attribute("failures").as_int(), 2);
  EXPECT_EQ(suites.attribute("skipped").as_int(), 2);
  EXPECT_EQ(suites.attribute("errors").as_int(), 0);
  int suites_seen = 0, cases_seen = 0;
  for (auto suite : suites.children("testsuite")) {
    ++suites_seen;
    int tests = 0, failures = 0, skipped = 0;
    for (auto tc : suite.children("testcase")) {
      ++tests;
      ++cases_seen;
      EXPECT_EQ(std::string(tc.attribute("classname").value()),
                "regress." + std::string(suite.attribute("name").value()));
      EXPECT_GE(tc.attribute("time").as_double(-1), 0.0);
      const std::string id =
          std::string(suite.attribute("name").value()) + "/" + tc.attribute("name").value();
      if (auto f = tc.child("failure")) {
        ++failures;
        const std::string message = f.attribute("message").value();
        if (id == "quad_a/glsl:pow=exact") {
          EXPECT_STREQ(f.attribute("type").value(), "regress");
          EXPECT_NE(message.find("(max 9.000 LSB at 5,5 R)"), std::string::npos) << message;
          EXPECT_NE(std::string(f.text().get()).find("PSNR dB"), std::string::npos);
        } else {
          EXPECT_EQ(id, "quad_b/combiners:t=vertex");
          EXPECT_STREQ(f.attribute("type").value(), "missing-golden");
          EXPECT_NE(message.find("--update"), std::string::npos) << message;
        }
      }
      if (tc.child("skipped")) ++skipped;
    }
    EXPECT_EQ(suite.attribute("tests").as_int(), tests);
    EXPECT_EQ(suite.attribute("failures").as_int(), failures);
    EXPECT_EQ(suite.attribute("skipped").as_int(), skipped);
  }
  EXPECT_EQ(suites_seen, 2);
  EXPECT_EQ(cases_seen, 8);
}

TEST_F(Regress, TheScenesRegressBlockOverridesThePathsDefault) {
  run_regress(options(true));
  test::push_pixel(dir / "goldens" / "quad_a__glsl.png", 20, 15, 6);
  test::push_pixel(dir / "goldens" / "quad_a__reference.png", 20, 15, 6);
  // Only glsl may be 8 LSB off in this scene; the reference keeps the default.
  test::write_quad_scene(dir.path(), "quad_a", 4,
                         R"("regress": {"paths": {"glsl": {"hard_fail_lsb": 8}}})");
  const RegressRun run = run_regress(options());
  // Within the scene's 8 LSB, in the warn tier (it differs from its golden).
  EXPECT_EQ(find(run, "quad_a/glsl/pow=exact").status, CaseStatus::kWarn);
  EXPECT_EQ(find(run, "quad_a/glsl/pow=exact").regress_case.tolerance.hard_fail_lsb, 8.0);
  EXPECT_EQ(find(run, "quad_a/reference/exact").status, CaseStatus::kFail);
  test::write_quad_scene(dir.path(), "quad_a", 4,
                         R"("regress": {"hard_fail_lsb": 8, "fail_percent": 1})");
  EXPECT_FALSE(run_regress(options()).failed());

  for (const auto& [block, key] : std::vector<std::pair<std::string, std::string>>{
           {R"("regress": {"paths": {"nope": {}}})", "regress.paths.nope"},
           {R"("regress": {"fail_lsb": -1})", "regress.fail_lsb"},
           {R"("regress": {"region": "all"})", "regress.region"},
           {R"("regress": {"paths": {"glsl": {"hard_fail": 8}}})", "regress.paths.glsl.hard_fail"},
           {R"("regress": {"tolerance": 8})", "regress.tolerance"}}) {
    test::write_quad_scene(dir.path(), "quad_a", 4, block);
    try {
      run_regress(options());
      ADD_FAILURE() << block << " was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), key) << e.what();
      EXPECT_EQ(e.file(), (dir / "quad_a.json").string());
    }
  }
}

// The page lists every case, each card with its verdict and the figures the JSON has.
TEST_F(Regress, ThePageListsEveryCaseWithItsFigures) {
  run_regress(options(true));
  test::push_pixel(dir / "goldens" / "quad_b__reference.png", 30, 12, 12);
  RegressOptions o = options();
  o.report_dir = dir / "report";
  o.json_file = dir / "r.json";
  const RegressRun run = run_regress(o);
  write_regress_outputs(o, run);
  const std::string html = test::read_file(dir / "report" / "index.html");
  const auto j = nlohmann::json::parse(test::read_file(dir / "r.json"));
  ASSERT_EQ(j["cases"].size(), 6u);
  EXPECT_EQ(j["counts"]["fail"], 1);
  for (const auto& c : j["cases"]) {
    const std::string id = c["id"];
    const size_t at = html.find("data-case=\"" + id + "\"");
    ASSERT_NE(at, std::string::npos) << id;
    const std::string card = html.substr(at, html.find("</article>", at) - at);
    EXPECT_NE(card.find("data-verdict=\"" + c["status"].get<std::string>() + "\""),
              std::string::npos)
        << card;
    char max[64];
    std::snprintf(max, sizeof max, "<dt>max</dt><dd>%.2f LSB</dd>",
                  c["comparison"]["image"]["max_lsb"].get<double>());
    EXPECT_NE(card.find(max), std::string::npos) << id << ": " << card;
    for (const char* img : {"images/", "__golden.png", "__heatmap.png"})
      EXPECT_NE(card.find(img), std::string::npos) << id << " " << img;
  }
  const size_t failing = html.find("data-case=\"quad_b/reference/exact\"");
  EXPECT_NE(html.substr(failing, 400).find("data-failing=\"yes\""), std::string::npos);
  EXPECT_NE(html.find("<dt>max</dt><dd>12.00 LSB</dd>"), std::string::npos);
  // Self-contained: no address outside the report folder.
  EXPECT_EQ(html.find("http://"), std::string::npos);
  EXPECT_EQ(html.find("https://"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir / "report" / "images"))
    EXPECT_EQ(e.path().extension(), ".png") << e.path();
}

}  // namespace
}  // namespace lt
