// Programs that are not ltrender's (Xvfb, Dolphin), run as children that can always be ended.
// Each starts in a process group of its own, so that it and whatever it starts in turn
// (Xvfb's xkbcomp, a shell script's `sleep`) are signalled together, and nothing else is: a
// group is only ever signalled while its leader is our unreaped child, so its id cannot have
// been reused. The destructor kills and reaps a child still running, so an exception on the
// way leaves no process behind. (core/sandboxed_child.h is the other kind of child: our own
// code, forked, capped; the two share reap().)
#pragma once

#include <sys/types.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace lt {

// waitpid(pid, 0) through EINTR; returns the wait status (0 if waitpid fails).
int reap(pid_t pid);

// "exited with status 1", "was killed by signal 11 (Segmentation fault)".
std::string describe_wait_status(int status);

// `name` as exec would find it: a name with a slash as it is, any other through $PATH. Empty
// when there is no such executable file.
std::filesystem::path find_executable(const std::string& name);

struct ChildProgram {
  std::filesystem::path executable;                // resolved (find_executable)
  std::vector<std::string> arguments;              // argv[1...]
  std::vector<std::string> environment_additions;  // "NAME=value", added to ours
  std::filesystem::path output;  // stdout and stderr go to this file (created or truncated)
  int inherited_fd = -1;         // one descriptor the program keeps open (Xvfb's -displayfd)
};

class ChildProcess {
 public:
  using Clock = std::chrono::steady_clock;

  // Starts the program. Throws std::runtime_error when it cannot be started at all (fork or
  // exec failed: the message says which, with errno's text).
  explicit ChildProcess(const ChildProgram& program);
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  pid_t pid() const { return pid_; }
  // Waits until the program has ended (not reaped yet) or `deadline` passes; true if it ended.
  bool wait_until(Clock::time_point deadline);
  // Sends `polite_signal` to the group, gives the program `grace` to end, then kills what is
  // left of the group, waits until all of it is dead (bounded) and reaps the program. Also
  // right after the program ended by itself: that kills anything it left running in its group.
  // Idempotent.
  void stop(int polite_signal, std::chrono::milliseconds grace);
  // After stop(): the wait status, for describe_wait_status().
  int wait_status() const { return status_; }
  bool stopped() const { return reaped_; }

 private:
  bool has_ended() const;
  pid_t pid_ = -1;
  int status_ = 0;
  bool reaped_ = false;
};

}  // namespace lt
