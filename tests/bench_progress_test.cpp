// The bench's progress line: the step N of M, what it is, the time left at the pace so far, and
// nothing at all when it is not drawn on a terminal (report/bench_progress.h).
#include "report/bench_progress.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace lt {
namespace {

// What `write` printed into a temporary file.
template <typename F>
std::string printed(F write) {
  std::FILE* f = std::tmpfile();
  EXPECT_NE(f, nullptr);
  write(f);
  std::fflush(f);
  std::rewind(f);
  std::string out;
  for (int c; (c = std::fgetc(f)) != EOF;) out += static_cast<char>(c);
  std::fclose(f);
  return out;
}

TEST(BenchProgress, TimeLeftIsThePaceSoFarTimesTheStepsLeft) {
  EXPECT_FALSE(seconds_left(0, 10, 5.0));                    // nothing done: no pace to go by
  EXPECT_DOUBLE_EQ(seconds_left(2, 10, 5.0).value(), 20.0);  // 2.5 s a step, 8 to go
  EXPECT_DOUBLE_EQ(seconds_left(10, 10, 7.0).value(), 0.0);
  EXPECT_FALSE(seconds_left(11, 10, 7.0));
}

TEST(BenchProgress, TimeLeftInWords) {
  EXPECT_EQ(time_left_words(std::nullopt), "");
  EXPECT_EQ(time_left_words(42.4), "about 42 s left");
  EXPECT_EQ(time_left_words(59.4), "about 59 s left");
  EXPECT_EQ(time_left_words(130.0), "about 2 min 10 s left");
  EXPECT_EQ(time_left_words(134.0), "about 2 min 10 s left");  // to 10 s above a minute
  EXPECT_EQ(time_left_words(3600.0), "about 60 min 0 s left");
}

TEST(BenchProgress, LineNamesThePhaseTheStepAndWhatItIs) {
  EXPECT_EQ(progress_line("timing", 3, 80, "backlit_sphere, gx t=vertex:lut=16", 40.0),
            "bench: timing 3 of 80: backlit_sphere, gx t=vertex:lut=16, about 40 s left");
  EXPECT_EQ(progress_line("renders", 1, 2, "quad, glsl pow=exact", std::nullopt),
            "bench: renders 1 of 2: quad, glsl pow=exact");
}

TEST(BenchProgress, OnATerminalTheLineIsRedrawnInPlace) {
  const std::string out = printed([](std::FILE* f) {
    BenchProgress p(true, true, f);
    p.start_phase("renders", 2);
    p.step("quad, glsl pow=exact");
    p.step("quad, flat constant");
  });
  EXPECT_EQ(out,
            "\r\033[Kbench: renders 1 of 2: quad, glsl pow=exact"
            "\r\033[Kbench: renders 2 of 2: quad, flat constant"
            "\r\033[K");  // cleared when the bench ends
  EXPECT_EQ(out.find('\n'), std::string::npos);
}

TEST(BenchProgress, ANoteStaysAboveTheLine) {
  const std::string out = printed([](std::FILE* f) {
    BenchProgress p(true, true, f);
    p.start_phase("renders", 2);
    p.step("a");
    p.note("bench: quad: gx t=texgen skipped: perspective");
  });
  EXPECT_EQ(out,
            "\r\033[Kbench: renders 1 of 2: a\r\033[K"
            "bench: quad: gx t=texgen skipped: perspective\n");
}

TEST(BenchProgress, OffATerminalOnlyTheNotesArePrinted) {
  const std::string out = printed([](std::FILE* f) {
    BenchProgress p(false, true, f);
    p.start_phase("renders", 2);
    p.step("a");
    p.note("a note");
    p.step("b");
  });
  EXPECT_EQ(out, "a note\n");
  const std::string quiet = printed([](std::FILE* f) {
    BenchProgress p(false, false, f);
    p.start_phase("renders", 1);
    p.step("a");
    p.note("a note");
  });
  EXPECT_EQ(quiet, "");
}

}  // namespace
}  // namespace lt
