// Pinning the process to one core (bench --pin-core, issue 11): every thread running at the time
// moves, and threads started later inherit the core; a core the process may not use is refused.
#include "core/cpu_affinity.h"

#include <gtest/gtest.h>
#include <sched.h>
#include <unistd.h>

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "core/parallel_rows.h"

namespace lt {
namespace {

std::vector<int> cores_of(pid_t tid) {
  cpu_set_t set;
  CPU_ZERO(&set);
  EXPECT_EQ(sched_getaffinity(tid, sizeof(set), &set), 0);
  std::vector<int> out;
  for (int c = 0; c < CPU_SETSIZE; ++c) {
    if (CPU_ISSET(c, &set)) out.push_back(c);
  }
  return out;
}

TEST(CpuAffinity, PinningMovesRunningThreadsAndNewOnesInherit) {
  const std::vector<int> original = allowed_cores();
  ASSERT_FALSE(original.empty());
  // A thread started before the pinning, parked until the test has looked at it.
  std::mutex m;
  std::condition_variable cv;
  bool release = false;
  std::atomic<pid_t> early_tid{0};
  std::thread early([&] {
    early_tid = gettid();
    std::unique_lock<std::mutex> lock(m);
    cv.wait(lock, [&] { return release; });
  });
  while (early_tid == 0) std::this_thread::yield();

  const int core = original.back();
  ASSERT_TRUE(pin_process_to_core(core));
  EXPECT_EQ(allowed_cores(), std::vector<int>{core});
  EXPECT_EQ(cores_of(early_tid), std::vector<int>{core});  // moved while it ran
  std::vector<int> later;
  std::thread([&] { later = allowed_cores(); }).join();
  EXPECT_EQ(later, std::vector<int>{core});  // inherited
  // The CPU paths' default workers follow the mask: one on one core.
  EXPECT_EQ(usable_core_count(), 1u);
  EXPECT_EQ(worker_threads(), 1u);

  {
    std::lock_guard<std::mutex> lock(m);
    release = true;
  }
  cv.notify_one();
  early.join();
  ASSERT_TRUE(set_process_cores(original));  // the rest of the suite runs unpinned
  EXPECT_EQ(allowed_cores(), original);
}

TEST(CpuAffinity, ACoreTheProcessMayNotUseIsRefused) {
  const std::vector<int> before = allowed_cores();
  EXPECT_FALSE(pin_process_to_core(CPU_SETSIZE - 1));
  EXPECT_FALSE(pin_process_to_core(-1));
  EXPECT_EQ(allowed_cores(), before);
}

}  // namespace
}  // namespace lt
