#include "core/child_process.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char** environ;

namespace lt {

namespace {

// A descriptor closed when it goes out of scope.
class Fd {
 public:
  explicit Fd(int fd = -1) : fd_(fd) {}
  ~Fd() { close(); }
  Fd(const Fd&) = delete;
  Fd& operator=(const Fd&) = delete;
  int get() const { return fd_; }
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
};

std::string errno_text(const std::string& what, int error) {
  return what + ": " + std::strerror(error);
}

// Our environment with `additions` replacing the variables of the same name.
std::vector<std::string> merged_environment(const std::vector<std::string>& additions) {
  std::vector<std::string> out;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry = *e;
    const std::string name = entry.substr(0, entry.find('='));
    const bool replaced = std::any_of(additions.begin(), additions.end(), [&](const auto& a) {
      return a.compare(0, name.size() + 1, name + "=") == 0;
    });
    if (!replaced) out.push_back(entry);
  }
  out.insert(out.end(), additions.begin(), additions.end());
  return out;
}

std::vector<char*> pointers(std::vector<std::string>& strings) {
  std::vector<char*> out;
  for (auto& s : strings) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

// Between fork and exec only async-signal-safe calls: the parent may have threads.
[[noreturn]] void exec_child(const char* path, char* const* argv, char* const* envp, int in_fd,
                             int out_fd, int kept_fd, int error_fd, pid_t parent) {
  ::setpgid(0, 0);
  // A parent that dies without stopping us (killed, or ended by Ctrl-C, which our own group
  // does not receive) takes the program with it.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (::getppid() != parent) ::_exit(127);
  // Dispositions set to "ignore" survive exec: give the program the defaults.
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGCHLD})
    ::sigaction(sig, &default_action, nullptr);
  sigset_t none;
  ::sigemptyset(&none);
  ::sigprocmask(SIG_SETMASK, &none, nullptr);
  ::dup2(in_fd, 0);
  ::dup2(out_fd, 1);
  ::dup2(out_fd, 2);
  if (kept_fd >= 0) ::fcntl(kept_fd, F_SETFD, 0);
  ::execve(path, argv, envp);
  const int error = errno;
  [[maybe_unused]] const auto written = ::write(error_fd, &error, sizeof error);
  ::_exit(127);
}

// Whether a process of group `pgid` is still alive (neither a zombie nor dead), from
// /proc/PID/stat: its state is the field after the command's closing parenthesis, the group the
// third after it [proc(5)]. The command may itself hold spaces and parentheses, hence the last ')'.
bool group_has_a_live_process(pid_t pgid) {
  std::error_code error;
  for (std::filesystem::directory_iterator it("/proc", error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(it->path() / "stat");
    std::string stat;
    if (!std::getline(in, stat)) continue;  // it ended while we looked
    const std::size_t close = stat.rfind(')');
    if (close == std::string::npos) continue;
    std::istringstream fields(stat.substr(close + 1));
    char state = 0;
    long ppid = 0, group = 0;
    if (!(fields >> state >> ppid >> group)) continue;
    if (group == pgid && state != 'Z' && state != 'X') return true;
  }
  return false;
}

}  // namespace

int reap(pid_t pid) {
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) return 0;
  }
  return status;
}

std::string describe_wait_status(int status) {
  if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    const char* name = ::sigdescr_np(sig);
    return "was killed by signal " + std::to_string(sig) +
           (name ? " (" + std::string(name) + ")" : "");
  }
  return "ended with wait status " + std::to_string(status);
}

std::filesystem::path find_executable(const std::string& name) {
  const auto runnable = [](const std::filesystem::path& p) {
    struct stat st {};
    return ::stat(p.c_str(), &st) == 0 && S_ISREG(st.st_mode) && ::access(p.c_str(), X_OK) == 0;
  };
  if (name.empty()) return {};
  if (name.find('/') != std::string::npos) {
    return runnable(name) ? std::filesystem::path(name) : std::filesystem::path{};
  }
  const char* path_env = std::getenv("PATH");
  const std::string path = path_env ? path_env : "/usr/local/bin:/usr/bin:/bin";
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = path.find(':', begin);
    const std::string dir = path.substr(begin, end == std::string::npos ? end : end - begin);
    const std::filesystem::path candidate = (dir.empty() ? "." : dir) + ("/" + name);
    if (runnable(candidate)) return candidate;
    if (end == std::string::npos) return {};
    begin = end + 1;
  }
}

ChildProcess::ChildProcess(const ChildProgram& program) {
  std::vector<std::string> argv_strings = {program.executable.string()};
  argv_strings.insert(argv_strings.end(), program.arguments.begin(), program.arguments.end());
  std::vector<std::string> env_strings = merged_environment(program.environment_additions);
  const std::vector<char*> argv = pointers(argv_strings);
  const std::vector<char*> envp = pointers(env_strings);

  Fd in(::open("/dev/null", O_RDONLY | O_CLOEXEC));
  Fd out(::open(program.output.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644));
  if (in.get() < 0 || out.get() < 0)
    throw std::runtime_error(errno_text("cannot open " + program.output.string(), errno));
  // Exec closes the write end (O_CLOEXEC): reading nothing means exec succeeded.
  int error_pipe[2];
  if (::pipe2(error_pipe, O_CLOEXEC) != 0) throw std::runtime_error(errno_text("pipe", errno));
  Fd error_read(error_pipe[0]), error_write(error_pipe[1]);

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(errno_text("fork", errno));
  if (pid == 0) {
    exec_child(argv[0], argv.data(), envp.data(), in.get(), out.get(), program.inherited_fd,
               error_write.get(), parent);
  }
  // Also here: the group must exist before we may signal it, whichever of us runs first.
  ::setpgid(pid, pid);
  pid_ = pid;
  error_write.close();
  int exec_error = 0;
  ssize_t got;
  do {
    got = ::read(error_read.get(), &exec_error, sizeof exec_error);
  } while (got < 0 && errno == EINTR);
  if (got == static_cast<ssize_t>(sizeof exec_error)) {
    status_ = reap(pid_);
    reaped_ = true;
    throw std::runtime_error(errno_text("cannot run " + program.executable.string(), exec_error));
  }
}

ChildProcess::~ChildProcess() {
  stop(0, std::chrono::milliseconds(0));
}

bool ChildProcess::has_ended() const {
  siginfo_t info{};
  // WNOWAIT: the program stays a zombie, so its group id stays ours until stop() reaps it.
  if (::waitid(P_PID, static_cast<id_t>(pid_), &info, WEXITED | WNOHANG | WNOWAIT) != 0)
    return true;  // not our child any more: nothing to wait for
  return info.si_pid != 0;
}

bool ChildProcess::wait_until(Clock::time_point deadline) {
  if (reaped_) return true;
  // Polled every 10 ms: cheap, and precise enough for deadlines counted in seconds.
  for (;;) {
    if (has_ended()) return true;
    const auto left = deadline - Clock::now();
    if (left <= Clock::duration::zero()) return false;
    std::this_thread::sleep_for(std::min<Clock::duration>(left, std::chrono::milliseconds(10)));
  }
}

void ChildProcess::stop(int polite_signal, std::chrono::milliseconds grace) {
  if (reaped_ || pid_ <= 0) return;
  if (polite_signal != 0 && !has_ended()) {
    ::kill(-pid_, polite_signal);
    wait_until(Clock::now() + grace);
  }
  ::kill(-pid_, SIGKILL);
  // kill() returns before the group has died: a member not yet scheduled since is still running
  // (and still reads its files) for a moment, longer on a loaded machine. So wait until every
  // member is dead, before reaping the leader, whose zombie keeps the group id from being
  // reused meanwhile. SIGKILL cannot be caught: the bound is only against the unforeseen.
  const auto bound = Clock::now() + std::chrono::seconds(5);
  while (group_has_a_live_process(pid_) && Clock::now() < bound)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  status_ = reap(pid_);
  reaped_ = true;
}

}  // namespace lt
