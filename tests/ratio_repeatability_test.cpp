// scripts/ratio_repeatability.py, the table of issue 11's three-run check, on report.json files
// written here with known ratios: it must take each path's first variant only, and its median and
// worst deviation are worked out by hand below.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.h"

namespace lt {
namespace {

nlohmann::json ratio_row(const std::string& path, const std::string& variant, double ratio) {
  return {{"scene", "s"},
          {"path", path},
          {"variant", variant},
          {"ratio_to_flat", ratio},
          {"ratio_interval", {{"low", ratio * 0.9}, {"high", ratio * 1.1}, {"pairs", 10}}}};
}

std::string script() {
  return "python3 " + (test::source_dir() / "scripts" / "ratio_repeatability.py").string();
}

TEST(RatioRepeatability, DefaultVariantsMedianAndWorstDeviation) {
  const fs::path dir = fs::temp_directory_path() / ("lt_repeat_" + std::to_string(::getpid()));
  std::string args;
  const double gx[] = {10, 12, 11}, lut16[] = {1, 50, 3};
  for (int run = 0; run < 3; ++run) {
    const fs::path d = dir / ("run" + std::to_string(run));
    fs::create_directories(d);
    const nlohmann::json report = {
        {"rows",
         {ratio_row("flat", "constant", 1), ratio_row("gx", "t=vertex", gx[run]),
          ratio_row("gx", "t=vertex:lut=16", lut16[run])}}};
    test::write_file(d / "report.json", report.dump());
    args += " " + d.string();
  }
  const test::CommandOutput r = test::command_output(script() + args);
  EXPECT_EQ(r.exit_code, 0) << r.out;
  // Median 11; the worst run is 1 off, 1/11 = 9.1%; run 1's interval is 10 x (0.9, 1.1).
  EXPECT_NE(
      r.out.find("| s | gx | t=vertex | 10.000 | 12.000 | 11.000 | 11.000 | 9.1% | 9.00-11.00 |"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("| gx | 9.1% |"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("lut=16"), std::string::npos) << r.out;  // not a default variant
  EXPECT_EQ(r.out.find("| s | flat"), std::string::npos) << r.out;

  // A run without a report is an error naming the file, exit 2.
  const test::CommandOutput bad = test::command_output(script() + " " + (dir / "run0").string() +
                                                       " " + (dir / "missing").string() + " 2>&1");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.out.find("missing/report.json"), std::string::npos) << bad.out;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lt
