#include "core/cpu_affinity.h"

#include <sched.h>
#include <sys/types.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace lt {

std::vector<int> allowed_cores() {
  cpu_set_t set;
  CPU_ZERO(&set);
  std::vector<int> cores;
  if (sched_getaffinity(0, sizeof(set), &set) != 0) return cores;
  for (int c = 0; c < CPU_SETSIZE; ++c) {
    if (CPU_ISSET(c, &set)) cores.push_back(c);
  }
  return cores;
}

unsigned usable_core_count() {
  return std::max<unsigned>(1, static_cast<unsigned>(allowed_cores().size()));
}

bool pin_process_to_core(int core) {
  const std::vector<int> allowed = allowed_cores();
  if (std::find(allowed.begin(), allowed.end(), core) == allowed.end()) return false;
  return set_process_cores({core});
}

bool set_process_cores(const std::vector<int>& cores) {
  cpu_set_t set;
  CPU_ZERO(&set);
  for (int c : cores) {
    if (c >= 0 && c < CPU_SETSIZE) CPU_SET(c, &set);
  }
  // Every thread running now: sched_setaffinity(0) would move only the calling one.
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    const pid_t tid = static_cast<pid_t>(std::stol(task.path().filename().string()));
    sched_setaffinity(tid, sizeof(set), &set);
  }
  // The calling thread for certain, even if /proc is not mounted.
  return sched_setaffinity(0, sizeof(set), &set) == 0;
}

}  // namespace lt
