#include "core/sandboxed_child.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "core/child_process.h"

#if defined(__SANITIZE_ADDRESS__)
#include <sanitizer/common_interface_defs.h>
#endif

namespace lt {

namespace {

// In a sanitized build a corrupt input's overflows and runaway allocations are sanitizer
// reports, which end the child with exit code 1 rather than a signal; the death callback gives
// them a code of their own, so the parent reports a crash as it does for the release build's
// signals. Only the child's death is handled: the sanitizer stays on everywhere.
constexpr int kChildSanitizerDied = 86;

void on_sanitizer_death_in_child() {
#if defined(__SANITIZE_ADDRESS__)
  __sanitizer_set_death_callback([] { ::_exit(kChildSanitizerDied); });
#endif
}

bool write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

// Caps the address space above what the child already maps, and its CPU time.
void limit_child(const SandboxLimits& limits) {
  char statm[128] = {};
  const int fd = ::open("/proc/self/statm", O_RDONLY);
  if (fd >= 0) {
    const auto got = ::read(fd, statm, sizeof statm - 1);
    ::close(fd);
    if (got > 0) {
      const std::size_t mapped =
          std::strtoull(statm, nullptr, 10) * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
      const rlimit as{mapped + limits.address_space_budget, mapped + limits.address_space_budget};
      ::setrlimit(RLIMIT_AS, &as);
    }
  }
  const auto seconds = static_cast<rlim_t>(limits.time_limit.count());
  const rlimit cpu{seconds, seconds};
  ::setrlimit(RLIMIT_CPU, &cpu);
}

[[noreturn]] void run_child(int out_fd, const SandboxLimits& limits,
                            const std::function<int(std::string&)>& work) {
  on_sanitizer_death_in_child();
  const int devnull = ::open("/dev/null", O_WRONLY);
  if (devnull >= 0) {
    ::dup2(devnull, 1);
    ::dup2(devnull, 2);
  }
  limit_child(limits);
  int code = 0;
  std::string payload;
  try {
    code = work(payload);
  } catch (const std::exception& e) {
    code = kSandboxWorkThrew;
    payload = e.what();
  }
  write_all(out_fd, payload);
  ::_exit(code);
}

}  // namespace

SandboxOutcome run_in_sandboxed_child(const SandboxLimits& limits,
                                      const std::function<int(std::string& payload)>& work) {
  SandboxOutcome outcome;
  int pipe_fds[2];
  if (::pipe(pipe_fds) != 0) {
    outcome.payload = "pipe() failed";
    return outcome;
  }
  std::cout.flush();
  std::cerr.flush();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(pipe_fds[0]);
    ::close(pipe_fds[1]);
    outcome.payload = "fork() failed";
    return outcome;
  }
  if (pid == 0) {
    ::close(pipe_fds[0]);
    run_child(pipe_fds[1], limits, work);
  }
  ::close(pipe_fds[1]);
  // Drain the pipe while the child works (it blocks once the pipe buffer is full).
  const auto deadline = std::chrono::steady_clock::now() + limits.time_limit;
  char buf[1 << 16];
  for (;;) {
    const auto left = deadline - std::chrono::steady_clock::now();
    if (left <= std::chrono::steady_clock::duration::zero()) {
      ::kill(pid, SIGKILL);
      reap(pid);
      ::close(pipe_fds[0]);
      outcome.end = SandboxOutcome::End::TimedOut;
      return outcome;
    }
    pollfd pfd{pipe_fds[0], POLLIN, 0};
    const int ready = ::poll(
        &pfd, 1,
        static_cast<int>(std::chrono::duration_cast<std::chrono::milliseconds>(left).count()) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline check above ends it
    const ssize_t n = ::read(pipe_fds[0], buf, sizeof buf);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // end of file: the child is done (or dead)
    outcome.payload.append(buf, static_cast<std::size_t>(n));
  }
  ::close(pipe_fds[0]);
  const int status = reap(pid);
  if (WIFSIGNALED(status)) {
    outcome.end = SandboxOutcome::End::Signalled;
    outcome.code = WTERMSIG(status);
  } else if (WIFEXITED(status) && WEXITSTATUS(status) == kChildSanitizerDied) {
    outcome.end = SandboxOutcome::End::SanitizerDied;
  } else {
    outcome.end = SandboxOutcome::End::Exited;
    outcome.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  return outcome;
}

}  // namespace lt
