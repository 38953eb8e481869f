// The report page in a real browser: headless Chromium (Debian's `chromium`, installed by
// scripts/setup.sh) opens the page of a regress run with one failing case and one missing
// golden. Through the DOM (the page's ?selftest writes its findings into #selftest-result, which
// `--dump-dom` prints after the page's JavaScript has run): every card's images loaded at their
// size, a flip changes the displayed image to the golden, and the "failing" filter shows exactly
// the cases regress failed. Screenshots go to build/test-output/report_page/ for a person, and a
// flipped screenshot must differ from the plain one in its pixels.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "core/build_paths.h"
#include "image/image.h"
#include "regress_fixture.h"
#include "test_util.h"

namespace lt {
namespace {

// The browser, or empty: Debian names it chromium.
std::string find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0)
      return name;
  }
  return "";
}

class ReportPageInBrowser : public ::testing::Test {
 protected:
  void SetUp() override {
    browser = find_chromium();
    ASSERT_FALSE(browser.empty()) << "no chromium: scripts/setup.sh installs Debian's chromium";
    fs::remove_all(out);
    fs::create_directories(out / "scenes");
    test::write_quad_scene(out / "scenes", "quad_a", 4);
    test::write_quad_scene(out / "scenes", "quad_b", 16);
    const std::string common = "regress " + (out / "scenes").string() + " --goldens " +
                               (out / "goldens").string() + " --paths reference,glsl,combiners";
    ASSERT_EQ(test::run_ltrender(common + " --update").exit_code, 0);
    // One golden far from its render (inverted), so its flip is plain to see; one missing.
    Image inverted = read_image(out / "goldens" / "quad_a__glsl.png");
    for (size_t i = 0; i < inverted.rgba.size(); ++i) {
      if (i % 4 != 3) inverted.rgba[i] = 1.0f - inverted.rgba[i];
    }
    write_image(out / "goldens" / "quad_a__glsl.png", inverted);
    fs::remove(out / "goldens" / "quad_b__combiners.png");
    const auto run = test::run_ltrender(common + " -o " + (out / "report").string() + " --json " +
                                        (out / "regress.json").string());
    ASSERT_EQ(run.exit_code, 1) << run.out << run.err;
    cases = nlohmann::json::parse(test::read_file(out / "regress.json"))["cases"];
    page = "file://" + (out / "report" / "index.html").string();
  }

  // Runs the browser headless on `url` with `what` (--dump-dom, --screenshot=FILE); returns
  // its stdout. A time budget lets the page's scripts and image loads finish first.
  std::string chromium(const std::string& url, const std::string& what) const {
    const fs::path stdout_file = out / "chromium.out";
    const std::string cmd = "timeout 120 " + browser +
                            " --headless --no-sandbox --disable-gpu --disable-dev-shm-usage"
                            " --hide-scrollbars --user-data-dir=" +
                            (out / "chromium-profile").string() +
                            " --window-size=1280,1000 --virtual-time-budget=10000 " + what + " '" +
                            url + "' >" + stdout_file.string() + " 2>" +
                            (out / "chromium.err").string();
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd << "\n" << test::read_file(out / "chromium.err");
    return test::read_file(stdout_file);
  }

  // One folder per test: ctest runs them side by side.
  const fs::path out = (lt::build_paths::binary_dir() / "test-output") / "report_page" /
                       ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::string browser, page;
  nlohmann::json cases;
};

// Text of the <pre id="selftest-result"> of a dumped DOM, unescaped.
nlohmann::json selftest_result(const std::string& dom) {
  const std::string open = "<pre id=\"selftest-result\">";
  const size_t at = dom.find(open);
  if (at == std::string::npos) return nullptr;
  std::string text = dom.substr(at + open.size(), dom.find("</pre>", at) - at - open.size());
  for (const auto& [entity, ch] : std::vector<std::pair<std::string, std::string>>{
           {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}}) {
    for (size_t p; (p = text.find(entity)) != std::string::npos;)
      text.replace(p, entity.size(), ch);
  }
  return nlohmann::json::parse(text);
}

TEST_F(ReportPageInBrowser, ImagesLoadFlipChangesTheImageAndTheFailureFilterIsExact) {
  const std::string dom = chromium(page + "?selftest", "--dump-dom");
  const nlohmann::json result = selftest_result(dom);
  ASSERT_FALSE(result.is_null()) << "the page's self test did not run:\n" << dom.substr(0, 2000);

  // Every case is a card, and every image of every card loaded at the render's size.
  ASSERT_EQ(cases.size(), 6u);
  EXPECT_EQ(result["cards"], cases.size());
  EXPECT_EQ(result["images"], 5 * 3 + 1) << "render, golden, heatmap; the missing one: render";
  EXPECT_TRUE(result["not_loaded"].empty()) << result["not_loaded"];
  size_t loaded = 0;
  for (size_t p = 0; (p = dom.find("data-loaded=\"yes\"", p)) != std::string::npos; ++p) ++loaded;
  EXPECT_EQ(loaded, cases.size());

  // The flip shows the golden where the render was: a different image, loaded.
  ASSERT_TRUE(result["flip"].is_object());
  const std::string flipped_case = result["flip"]["case"];
  const std::string stem =
      "images/" + flipped_case.substr(0, flipped_case.find('/')) + "__" +
      flipped_case.substr(flipped_case.find('/') + 1,
                          flipped_case.rfind('/') - flipped_case.find('/') - 1);
  EXPECT_EQ(result["flip"]["before"], stem + ".png");
  EXPECT_EQ(result["flip"]["after"], stem + "__golden.png");
  EXPECT_TRUE(result["flip"]["after_loaded"].get<bool>());

  // The failing filter shows exactly what regress failed (a failure and a missing golden).
  std::set<std::string> failed, shown;
  for (const auto& c : cases) {
    if (c["failed"].get<bool>()) failed.insert(c["id"].get<std::string>());
  }
  for (const auto& id : result["failing_shown"]) shown.insert(id.get<std::string>());
  EXPECT_EQ(failed, (std::set<std::string>{"quad_a/glsl/pow=exact", "quad_b/combiners/t=vertex"}));
  EXPECT_EQ(shown, failed);
  EXPECT_TRUE(result["charts"].empty()) << "regress's page has no chart";

  // bench's page draws its charts, the console's bytes beside speed and work: each laid out
  // at a size, its points there (flat has no error, so gx's: its default and a stored variant
  // added by name, whose legend entry is the longest a chart gets and must not be cut off). A
  // bench timed as briefly as bench allows: the page, not the figures, is under test.
  const fs::path bench_dir = out / "bench";
  const auto bench = test::run_ltrender(
      "bench " + (out / "scenes" / "quad_a.json").string() +
      " --paths gx --variants default --quick --min-time 0 --max-time 0 --warmup 0 --pin-core "
      "none --quiet --add-variant gx:t=vertex:vtx=s16/auto:nrm=s8:clr=rgb565:uv=s16/auto:draw=list "
      "-o " +
      bench_dir.string());
  ASSERT_EQ(bench.exit_code, 0) << bench.err;
  const nlohmann::json charts = selftest_result(chromium(
      "file://" + (bench_dir / "index.html").string() + "?selftest", "--dump-dom"))["charts"];
  ASSERT_EQ(charts.size(), 3u) << charts;
  EXPECT_EQ(charts[2]["title"],
            "Console bytes against error, per path and variant over all scenes");
  for (const auto& chart : charts) {
    EXPECT_EQ(chart["points"], 2) << chart;
    EXPECT_TRUE(chart["cut_text"].empty()) << chart;
    EXPECT_GT(chart["width"].get<int>(), 100) << chart;
    EXPECT_GT(chart["height"].get<int>(), 100) << chart;
  }
}

TEST_F(ReportPageInBrowser, ScreenshotsShowTheFlip) {
  const fs::path plain = out / "page.png", flipped = out / "page_flipped.png",
                 failing = out / "page_failing_heatmap.png";
  chromium(page, "--screenshot=" + plain.string());
  chromium(page + "?flip=all", "--screenshot=" + flipped.string());
  chromium(page + "?verdict=failing&heatmap=on&zoom=4", "--screenshot=" + failing.string());
  const Image a = read_image(plain), b = read_image(flipped), c = read_image(failing);
  ASSERT_EQ(a.width, 1280);
  ASSERT_EQ(a.height, b.height);
  size_t differ = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) differ += a.rgba[i] != b.rgba[i];
  // The inverted golden alone is 48x32 pixels at 2x zoom, at the top (failures first).
  EXPECT_GT(differ, 48u * 32u) << "flipping every card changed no pixels";
  size_t differ_failing = 0;
  for (size_t i = 0; i < a.rgba.size(); ++i) differ_failing += a.rgba[i] != c.rgba[i];
  EXPECT_GT(differ_failing, 0u);
  std::printf("screenshots: %s %s %s\n", plain.c_str(), flipped.c_str(), failing.c_str());
}

}  // namespace
}  // namespace lt
