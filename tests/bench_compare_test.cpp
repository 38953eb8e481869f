// bench --compare: a row counts as changed only when the intervals do not overlap (issue 11).
#include "report/bench_compare.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "test_util.h"

namespace lt {
namespace {

BenchRow row(const std::string& path, double low, double median, double high) {
  BenchRow r;
  r.scene = "s";
  r.path = path;
  r.variant = "v";
  r.ratio = {median, low, high, 20};
  r.ratio_to_flat = median;
  return r;
}

TEST(BenchCompare, OnlyIntervalsApartAreChanges) {
  EarlierBench before;
  before.rows = {{"s", "a", "v", {2.0, 1.9, 2.1, 20}},
                 {"s", "b", "v", {2.0, 1.9, 2.1, 20}},
                 {"s", "c", "v", {2.0, 1.9, 2.1, 20}},
                 {"s", "gone", "v", {1, 1, 1, 20}}};
  const std::vector<BenchRow> now = {row("a", 2.05, 2.2, 2.3),  // overlaps: noise
                                     row("b", 2.2, 2.3, 2.4),   // apart, slower
                                     row("c", 1.5, 1.6, 1.7),   // apart, faster
                                     row("new", 1, 1, 1)};
  const BenchComparison c = compare_bench(before, now);
  EXPECT_EQ(c.unchanged, 1u);
  ASSERT_EQ(c.changed.size(), 2u);
  EXPECT_EQ(c.changed[0].path, "b");
  EXPECT_TRUE(c.changed[0].slower());
  EXPECT_EQ(c.changed[1].path, "c");
  EXPECT_FALSE(c.changed[1].slower());
  EXPECT_EQ(c.slower(), 1u);
  EXPECT_EQ(c.only_now, 1u);
  EXPECT_EQ(c.only_before, 1u);
  const std::string md = comparison_markdown(before, c);
  EXPECT_NE(md.find("| s | b | v | 2.000 (1.900-2.100) | 2.300 (2.200-2.400) | slower +15.000% |"),
            std::string::npos)
      << md;
}

TEST(BenchCompare, ABadEarlierReportNamesTheFileAndKey) {
  test::TempDir dir;
  test::write_file(dir / "r.json", R"({"rows": [{"scene": "s", "path": 3, "variant": "v"}]})");
  try {
    read_earlier_bench(dir / "r.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("r.json:rows[0].path: expected a string"),
              std::string::npos)
        << e.what();
  }
  test::write_file(dir / "r.json", "not json");
  EXPECT_THROW(read_earlier_bench(dir / "r.json"), InputError);
}

// Through the binary: flat's ratio is 1 by definition, so an earlier report claiming 0.1-0.2 for
// it makes this run slower (exit 1, compare.md lists the row); against itself nothing changed.
TEST(BenchCompare, ExitsOneWhenARowIsSlower) {
  test::TempDir dir;
  const std::string scene = (test::source_dir() / "scenes" / "backlit_sphere.json").string();
  const std::string bench = "bench " + scene + " --paths flat --frames 10 --min-time 0 --quiet -o ";
  ASSERT_EQ(test::run_ltrender(bench + (dir / "first").string()).exit_code, 0);
  const auto same = test::run_ltrender(bench + (dir / "second").string() + " --compare " +
                                       (dir / "first" / "report.json").string());
  EXPECT_EQ(same.exit_code, 0) << same.err;
  EXPECT_NE(same.out.find("0 changed, 0 slower"), std::string::npos) << same.out;

  test::write_file(dir / "old.json", R"({"rows": [{"scene": "backlit_sphere", "path": "flat",
      "variant": "constant", "ratio_to_flat": 0.15,
      "ratio_interval": {"low": 0.1, "high": 0.2, "pairs": 10}}]})");
  const auto slower = test::run_ltrender(bench + (dir / "third").string() + " --compare " +
                                         (dir / "old.json").string());
  EXPECT_EQ(slower.exit_code, 1) << slower.err;
  EXPECT_NE(slower.err.find("1 rows slower than"), std::string::npos) << slower.err;
  EXPECT_NE(
      test::read_file(dir / "third" / "compare.md").find("| backlit_sphere | flat | constant |"),
      std::string::npos);
}

}  // namespace
}  // namespace lt
