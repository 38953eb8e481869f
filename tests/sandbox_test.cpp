// core/sandboxed_child: every way a child can end reaches the parent as its own outcome, and the
// parent survives each (the OM reader relies on this for corrupt files).
#include <gtest/gtest.h>
#include <unistd.h>

#include <csignal>
#include <new>
#include <stdexcept>
#include <vector>

#include "core/sandboxed_child.h"

namespace lt {
namespace {

using End = SandboxOutcome::End;

SandboxLimits one_second() {
  SandboxLimits limits;
  limits.time_limit = std::chrono::seconds(1);
  return limits;
}

TEST(SandboxedChild, ReturnsThePayloadAndTheExitCode) {
  const std::string big(300000, 'x');  // more than a pipe buffer: the parent must drain it
  const auto got = run_in_sandboxed_child(one_second(), [&](std::string& payload) {
    payload = big;
    return 7;
  });
  EXPECT_EQ(got.end, End::Exited);
  EXPECT_EQ(got.code, 7);
  EXPECT_EQ(got.payload, big);
}

TEST(SandboxedChild, AnExceptionIsItsMessage) {
  const auto got = run_in_sandboxed_child(
      one_second(), [](std::string&) -> int { throw std::runtime_error("reader gave up"); });
  EXPECT_EQ(got.end, End::Exited);
  EXPECT_EQ(got.code, kSandboxWorkThrew);
  EXPECT_EQ(got.payload, "reader gave up");
}

TEST(SandboxedChild, ACrashIsASignalOrASanitizerReport) {
  const auto got = run_in_sandboxed_child(one_second(), [](std::string&) {
    std::raise(SIGSEGV);
    return 0;
  });
  EXPECT_TRUE(got.end == End::Signalled || got.end == End::SanitizerDied);
  if (got.end == End::Signalled) EXPECT_EQ(got.code, SIGSEGV);
}

TEST(SandboxedChild, AHangIsKilledAtTheDeadline) {
  const auto start = std::chrono::steady_clock::now();
  const auto got = run_in_sandboxed_child(one_second(), [](std::string&) {
    ::sleep(30);  // no CPU time: only the wall-clock deadline can end it
    return 0;
  });
  EXPECT_EQ(got.end, End::TimedOut);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(10));
}

TEST(SandboxedChild, ARunawayAllocationFailsInsideTheChild) {
  SandboxLimits limits = one_second();
  limits.address_space_budget = std::size_t{64} << 20;
  const auto got = run_in_sandboxed_child(limits, [](std::string& payload) {
    try {
      std::vector<char> huge(std::size_t{4} << 30, 1);  // 4 GiB against a 64 MiB budget
      payload = std::to_string(huge.size());
      return 0;
    } catch (const std::bad_alloc&) {
      payload = "bad_alloc";
      return 1;
    }
  });
  // Sanitized builds report the allocation instead of returning null.
  if (got.end == End::SanitizerDied) GTEST_SKIP() << "the sanitizer ended the child";
  EXPECT_EQ(got.end, End::Exited);
  EXPECT_EQ(got.code, 1);
  EXPECT_EQ(got.payload, "bad_alloc");
}

}  // namespace
}  // namespace lt
