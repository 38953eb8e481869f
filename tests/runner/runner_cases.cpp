// Cases that end every way a case can end, for tests/runner/runner_test.py: the batch runner
// must report each one and go on after a crash or a hang. Not a ctest test of its own.
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>

TEST(Cases, Passes) {
  EXPECT_EQ(1 + 1, 2);
}
TEST(Cases, Fails) {
  EXPECT_EQ(1 + 1, 3) << "on purpose";
}
TEST(Cases, Skips) {
  GTEST_SKIP() << "on purpose";
}
TEST(Cases, Aborts) {
  std::abort();
}
TEST(Cases, RunsAfterTheAbort) {
  SUCCEED();
}
TEST(Cases, Segfaults) {
  std::raise(SIGSEGV);
}
TEST(Cases, ExitsMidway) {
  std::exit(0);
}
TEST(Cases, Hangs) {
  // A child in the case's process group, as Dolphin or Xvfb would be: it must not outlive it.
  if (::fork() == 0) {
    ::execlp("sleep", "sleep", "31", nullptr);
    ::_exit(127);
  }
  ::sleep(30);
}
TEST(Cases, RunsAfterTheHang) {
  SUCCEED();
}
TEST(Skipping, First) {
  GTEST_SKIP();
}
TEST(Skipping, Second) {
  GTEST_SKIP();
}
TEST(Leaving, AChildThatHoldsTheOutputOpen) {
  // Passes, and leaves a child holding stdout: the batch must end when the process does.
  if (::fork() == 0) {
    ::execlp("sleep", "sleep", "32", nullptr);
    ::_exit(127);
  }
  SUCCEED();
}
