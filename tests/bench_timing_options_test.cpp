// bench's timing modes on the command line: --quick is one round and a short minimum, --precise
// (the default) the CI standard, and each of the four settings takes the last value given, a
// mode counting as a value of all four (cli/bench_timing_options.h).
#include "cli/bench_timing_options.h"

#include <gtest/gtest.h>

#include <string>

namespace lt::cli {
namespace {

// The options as `bench ARGS` leaves them, without running a bench.
BenchOptions parsed(const std::string& args) {
  CLI::App app;
  CLI::App* bench = app.add_subcommand("bench");
  BenchOptions o;
  const auto apply = add_timing_options(*bench, o);
  app.parse("bench " + args, false);
  apply();
  return o;
}

TEST(BenchTimingOptions, WithoutOptionsTheTimingIsPrecise) {
  const BenchOptions o = parsed("");
  EXPECT_EQ(o.timing_mode, TimingMode::Precise);
  EXPECT_STREQ(to_string(o.timing_mode), "precise");
  EXPECT_EQ(o.rounds, 5);  // metrics.md's repeatability: five rounds to a +-2% interval
  EXPECT_DOUBLE_EQ(o.target_interval, 0.02);
  EXPECT_GT(o.max_time_s, o.min_time_s);
  EXPECT_TRUE(o.timing_overrides.empty());
}

TEST(BenchTimingOptions, QuickIsOneRoundAndNoTimeBeyondItsMinimum) {
  const BenchOptions precise = parsed(""), quick = parsed("--quick");
  EXPECT_EQ(quick.timing_mode, TimingMode::Quick);
  EXPECT_STREQ(to_string(quick.timing_mode), "quick");
  EXPECT_EQ(quick.rounds, 1);
  EXPECT_LT(quick.min_time_s, precise.min_time_s);
  EXPECT_EQ(quick.max_time_s, quick.min_time_s);  // no pairs for the interval beyond the minimum
  EXPECT_TRUE(quick.timing_overrides.empty());
}

TEST(BenchTimingOptions, AnOptionAfterTheModeOverridesIt) {
  const BenchOptions o = parsed("--quick --rounds 3 --max-time 1.5");
  EXPECT_EQ(o.timing_mode, TimingMode::Quick);  // still called quick: the report says what changed
  EXPECT_EQ(o.rounds, 3);
  EXPECT_DOUBLE_EQ(o.max_time_s, 1.5);
  EXPECT_DOUBLE_EQ(o.min_time_s, parsed("--quick").min_time_s);
  EXPECT_EQ(o.timing_overrides, (std::vector<std::string>{"--rounds", "--max-time"}));
}

TEST(BenchTimingOptions, AnOptionBeforeTheModeIsOverriddenByIt) {
  const BenchOptions o = parsed("--rounds 3 --min-time 2 --quick");
  EXPECT_EQ(o.rounds, 1);
  EXPECT_DOUBLE_EQ(o.min_time_s, parsed("--quick").min_time_s);
  EXPECT_TRUE(o.timing_overrides.empty());
}

TEST(BenchTimingOptions, TheLastValueOfAnOptionWinsAcrossTheMode) {
  // scripts/demo.sh: its own --max-time, then run.sh's arguments.
  const BenchOptions o = parsed("--max-time 0.5 --quick --max-time 1");
  EXPECT_DOUBLE_EQ(o.max_time_s, 1.0);
  EXPECT_EQ(o.rounds, 1);
  EXPECT_EQ(o.timing_overrides, (std::vector<std::string>{"--max-time"}));
}

TEST(BenchTimingOptions, OfTwoModesTheLastWins) {
  const BenchOptions quick_then_precise = parsed("--quick --precise");
  EXPECT_EQ(quick_then_precise.timing_mode, TimingMode::Precise);
  EXPECT_EQ(quick_then_precise.rounds, 5);
  const BenchOptions precise_then_quick = parsed("--precise --quick");
  EXPECT_EQ(precise_then_quick.timing_mode, TimingMode::Quick);
  EXPECT_EQ(precise_then_quick.rounds, 1);
}

TEST(BenchTimingOptions, AnOptionWithoutAModeOverridesThePreciseDefault) {
  const BenchOptions o = parsed("--max-time 0.5");
  EXPECT_EQ(o.timing_mode, TimingMode::Precise);
  EXPECT_DOUBLE_EQ(o.max_time_s, 0.5);
  EXPECT_EQ(o.rounds, 5);
  EXPECT_EQ(o.timing_overrides, (std::vector<std::string>{"--max-time"}));
}

TEST(BenchTimingOptions, OutOfRangeRoundsAreAUsageError) {
  EXPECT_THROW(parsed("--rounds 0"), CLI::ValidationError);
  EXPECT_THROW(parsed("--quick --min-time nan"), CLI::ValidationError);
}

}  // namespace
}  // namespace lt::cli
