#include "judge/private_display.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <stdexcept>

#include "judge/log_tail.h"

namespace lt::judge {

namespace {

// Reads what Xvfb writes to the -displayfd pipe, up to its newline: the display number
// [Xvfb(1) -displayfd]. Empty when the pipe reaches its end (the server ended) or the deadline
// passes first; `timed_out` says which.
std::string read_display_number(int fd, ChildProcess::Clock::time_point deadline, bool& timed_out) {
  std::string text;
  timed_out = false;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - ChildProcess::Clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      return "";
    }
    pollfd pfd{fd, POLLIN, 0};
    const int ready = ::poll(&pfd, 1, static_cast<int>(left.count()) + 1);
    if (ready < 0 && errno == EINTR) continue;
    if (ready <= 0) continue;  // the deadline check above ends it
    char c = 0;
    const ssize_t n = ::read(fd, &c, 1);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return "";
    if (c == '\n') return text;
    text += c;
  }
}

}  // namespace

PrivateDisplay::PrivateDisplay(const std::filesystem::path& xvfb, const std::filesystem::path& log,
                               const std::vector<std::string>& environment_additions,
                               ChildProcess::Clock::time_point deadline) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) throw std::runtime_error("Xvfb: pipe() failed");
  const int read_end = fds[0], write_end = fds[1];
  try {
    // -nolisten tcp: reachable only through its local socket; 24-bit colour so the GL
    // visual Dolphin asks for exists.
    server_ = std::make_unique<ChildProcess>(
        ChildProgram{xvfb,
                     {"-displayfd", std::to_string(write_end), "-nolisten", "tcp", "-screen", "0",
                      "1024x768x24"},
                     environment_additions,
                     log,
                     write_end});
  } catch (...) {
    ::close(read_end);
    ::close(write_end);
    throw;
  }
  // Only the server holds the write end now: its end is the pipe's end.
  ::close(write_end);
  bool timed_out = false;
  const std::string number = read_display_number(read_end, deadline, timed_out);
  ::close(read_end);
  if (number.empty() || number.find_first_not_of("0123456789") != std::string::npos) {
    server_->stop(SIGTERM, std::chrono::seconds(2));
    const std::string tail = log_tail(log);
    const std::string what =
        timed_out ? "Xvfb was not ready before the deadline"
                  : "Xvfb " + describe_wait_status(server_->wait_status()) + " before it was ready";
    throw std::runtime_error(what + (tail.empty() ? "" : "; its output ends: " + tail));
  }
  name_ = ":" + number;
}

PrivateDisplay::~PrivateDisplay() {
  if (server_) server_->stop(SIGTERM, std::chrono::seconds(2));
}

}  // namespace lt::judge
