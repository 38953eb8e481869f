// Work that may crash, hang or allocate without end (a library's reader fed a corrupt file) runs
// in a forked child with its address space and CPU time capped and a wall-clock deadline; it
// sends back bytes through a pipe, and the parent learns how it ended. The parent never runs
// the dangerous code, so nothing the child does can take the parent down.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace lt {

struct SandboxLimits {
  // Bytes the child may map beyond what the process maps when it forks (the inherited image,
  // GL included): a runaway allocation then fails instead of meeting the OOM killer.
  std::size_t address_space_budget = std::size_t{512} << 20;
  // CPU seconds (RLIMIT_CPU, SIGXCPU) and the parent's wall-clock deadline, after which the
  // child is killed.
  std::chrono::seconds time_limit{10};
};

struct SandboxOutcome {
  enum class End {
    Exited,         // `code` is the exit code of the work (0 ok)
    Signalled,      // `code` is the signal that ended the child
    SanitizerDied,  // a sanitizer report ended it (sanitized builds: ./test.sh --sanitize)
    TimedOut,       // killed at the deadline
    NotStarted,     // pipe() or fork() failed; `payload` says which
  };
  End end = End::NotStarted;
  int code = 0;
  std::string payload;  // what the work wrote into its payload
};

// Exit code of the child when `work` throws: the payload is then the exception's what().
inline constexpr int kSandboxWorkThrew = 3;

// Runs `work(payload)` in a child whose stdout and stderr go to /dev/null; the child exits with
// work's return value, or kSandboxWorkThrew if it throws. stdout and stderr are flushed before
// the fork so that nothing buffered is written twice.
SandboxOutcome run_in_sandboxed_child(const SandboxLimits& limits,
                                      const std::function<int(std::string& payload)>& work);

}  // namespace lt
