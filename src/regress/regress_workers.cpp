// The parent's side of regress_workers.h.
#include "regress/regress_workers.h"

#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <deque>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>

#include "core/child_process.h"
#include "core/fs.h"
#include "core/stopwatch.h"
#include "regress/case_record.h"

namespace lt {

namespace {

using Clock = SteadyClock;

// The last `count` lines of a worker's output (stdout and stderr): what it said before it died.
std::string output_tail(const fs::path& log, size_t count) {
  std::ifstream in(log);
  std::deque<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (line.empty()) continue;
    lines.push_back(line);
    if (lines.size() > count) lines.pop_front();
  }
  std::string out;
  for (const std::string& l : lines) out += (out.empty() ? "" : "\n") + l;
  return out;
}

std::string deadline_text(double seconds) {
  char text[32];
  std::snprintf(text, sizeof text, "%g s", seconds);
  return text;
}

struct Worker {
  std::unique_ptr<ChildProcess> process;
  int fd = -1;  // the parent's end of the socket
  fs::path log;
  std::string inbox;              // bytes read, not yet a whole line
  std::deque<size_t> assigned;    // positions sent and not finished, in order
  std::optional<size_t> running;  // the case it said it started
  Clock::time_point started_at;
  bool started_any = false;
};

class WorkerPool {
 public:
  WorkerPool(const RegressOptions& o, const RegressPlan& plan,
             const std::function<void(size_t, CaseResult)>& done)
      : o_(o), plan_(plan), done_(done), workers_(static_cast<size_t>(std::max(1, o.jobs))) {
    for (size_t i = 0; i < plan.cases.size(); ++i) position_of_[plan.cases[i].id()] = i;
    log_dir_ = fs::temp_directory_path() / ("ltrender-regress-" + std::to_string(::getpid()));
    fs::create_directories(log_dir_);
  }
  ~WorkerPool() {
    for (Worker& w : workers_) retire(w);
    std::error_code ec;
    fs::remove_all(log_dir_, ec);
  }

  void run(std::deque<std::vector<size_t>> batches, const std::function<void()>& tick) {
    for (;;) {
      for (Worker& w : workers_) {
        if (!w.assigned.empty()) continue;
        if (batches.empty()) {
          retire(w);  // nothing left for it: the worker reads the end and exits
          continue;
        }
        if (!w.process) start(w);
        send(w, batches.front());
        batches.pop_front();
      }
      bool busy = false;
      for (const Worker& w : workers_) busy = busy || !w.assigned.empty();
      if (!busy) return;
      wait_for_news(batches);
      tick();
    }
  }

 private:
  void start(Worker& w) {
    int sv[2];
    if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sv) != 0)
      throw std::runtime_error("regress: socketpair failed");
    ChildProgram p;
    p.executable = o_.worker_command.front();
    p.arguments.assign(o_.worker_command.begin() + 1, o_.worker_command.end());
    p.arguments.insert(p.arguments.end(), {kRegressWorkerOption, std::to_string(sv[1])});
    p.inherited_fd = sv[1];
    p.output = log_dir_ / ("worker-" + std::to_string(++started_) + ".log");
    try {
      w.process = std::make_unique<ChildProcess>(p);
    } catch (...) {
      ::close(sv[0]);
      ::close(sv[1]);
      throw;
    }
    ::close(sv[1]);
    w.fd = sv[0];
    w.log = p.output;
    w.inbox.clear();
    w.started_any = false;
  }

  void send(Worker& w, const std::vector<size_t>& batch) {
    nlohmann::json ids = nlohmann::json::array();
    for (size_t position : batch) ids.push_back(plan_.cases[position].id());
    const std::string line =
        nlohmann::json{{"scene", plan_.cases[batch.front()].scene_index}, {"cases", ids}}.dump() +
        "\n";
    w.assigned.assign(batch.begin(), batch.end());
    for (size_t sent = 0; sent < line.size();) {
      // MSG_NOSIGNAL: a worker that died already is found by the read that follows, not by a
      // SIGPIPE that would end the parent.
      const ssize_t n = ::send(w.fd, line.data() + sent, line.size() - sent, MSG_NOSIGNAL);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      sent += static_cast<size_t>(n);
    }
  }

  // Closes the socket (the worker ends at its end of input) and reaps the worker.
  void retire(Worker& w) {
    if (w.fd >= 0) ::close(w.fd);
    w.fd = -1;
    if (w.process) {
      w.process->wait_until(Clock::now() + std::chrono::seconds(5));
      w.process->stop(SIGKILL, std::chrono::milliseconds(0));
      w.process.reset();
    }
  }

  // Polls the workers until one speaks, dies, or a deadline passes (100 ms at most).
  void wait_for_news(std::deque<std::vector<size_t>>& batches) {
    std::vector<pollfd> fds;
    std::vector<Worker*> polled;
    int timeout_ms = 100;
    for (Worker& w : workers_) {
      if (w.fd < 0 || w.assigned.empty()) continue;
      fds.push_back({w.fd, POLLIN, 0});
      polled.push_back(&w);
      if (w.running && o_.case_timeout_seconds > 0) {
        const double left = o_.case_timeout_seconds -
                            std::chrono::duration<double>(Clock::now() - w.started_at).count();
        timeout_ms = std::min(timeout_ms, std::max(0, static_cast<int>(left * 1000.0) + 1));
      }
    }
    const int ready = ::poll(fds.data(), fds.size(), timeout_ms);
    if (ready < 0 && errno != EINTR) throw std::runtime_error("regress: poll failed");
    for (size_t k = 0; k < fds.size(); ++k) {
      Worker& w = *polled[k];
      if (fds[k].revents == 0) continue;
      char chunk[65536];
      const ssize_t n = ::read(w.fd, chunk, sizeof chunk);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) {
        lost(w, batches, std::nullopt);
        continue;
      }
      w.inbox.append(chunk, static_cast<size_t>(n));
      for (size_t end; (end = w.inbox.find('\n')) != std::string::npos;) {
        const std::string line = w.inbox.substr(0, end);
        w.inbox.erase(0, end + 1);
        hear(w, line);
      }
    }
    for (Worker& w : workers_) {
      if (!w.running || o_.case_timeout_seconds <= 0) continue;
      if (std::chrono::duration<double>(Clock::now() - w.started_at).count() >
          o_.case_timeout_seconds)
        lost(w, batches,
             "took longer than --case-timeout " + deadline_text(o_.case_timeout_seconds) +
                 "; its worker was stopped");
    }
  }

  void hear(Worker& w, const std::string& line) {
    const auto j = nlohmann::ordered_json::parse(line);
    if (j.contains("started")) {
      w.running = position_of_.at(j["started"].get<std::string>());
      w.started_at = Clock::now();
      w.started_any = true;
      startup_failures_ = 0;
      return;
    }
    const auto& record = j.at("result");
    const size_t position = position_of_.at(record.at("id").get<std::string>());
    CaseResult r = case_result_from_record(record, plan_.cases[position], "regress worker");
    w.running.reset();
    w.assigned.erase(std::find(w.assigned.begin(), w.assigned.end(), position));
    done_(position, std::move(r));
  }

  // A worker that died (`timeout` empty) or ran out of time: the case it was running fails with
  // the reason, the cases it had not started go back to the front of the queue, and the worker
  // is replaced when there is work for it.
  void lost(Worker& w, std::deque<std::vector<size_t>>& batches,
            const std::optional<std::string>& timeout) {
    if (w.fd >= 0) ::close(w.fd);
    w.fd = -1;
    if (!timeout) w.process->wait_until(Clock::now() + std::chrono::seconds(2));
    w.process->stop(SIGKILL, std::chrono::milliseconds(0));
    const int status = w.process->wait_status();
    w.process.reset();
    const std::string tail = output_tail(w.log, 20);
    if (w.running) {
      CaseResult r;
      r.regress_case = plan_.cases[*w.running];
      r.status = timeout ? CaseStatus::kTimedOut : CaseStatus::kCrashed;
      r.golden = o_.goldens / r.regress_case.golden_name();
      const std::string last =
          tail.substr(tail.rfind('\n') == std::string::npos ? 0 : tail.rfind('\n') + 1);
      r.message = timeout ? *timeout
                          : "its worker process " + describe_wait_status(status) +
                                (last.empty() ? "" : "; its last output: " + last);
      r.details = tail.empty() ? "" : "the worker's last output:\n" + tail + "\n";
      r.seconds = std::chrono::duration<double>(Clock::now() - w.started_at).count();
      const size_t position = *w.running;
      w.assigned.erase(std::find(w.assigned.begin(), w.assigned.end(), position));
      w.running.reset();
      done_(position, std::move(r));
    } else if (!w.started_any && ++startup_failures_ >= 2) {
      throw std::runtime_error("regress: worker processes end before their first case (the last " +
                               describe_wait_status(status) + "): " + tail);
    }
    if (!w.assigned.empty()) batches.emplace_front(w.assigned.begin(), w.assigned.end());
    w.assigned.clear();
  }

  const RegressOptions& o_;
  const RegressPlan& plan_;
  const std::function<void(size_t, CaseResult)>& done_;
  std::vector<Worker> workers_;
  std::map<std::string, size_t> position_of_;
  fs::path log_dir_;
  int started_ = 0, startup_failures_ = 0;
};

}  // namespace

void run_in_workers(const RegressOptions& o, const RegressPlan& plan,
                    const std::vector<size_t>& positions,
                    const std::function<void(size_t, CaseResult)>& done,
                    const std::function<void()>& tick) {
  // A scene's cases go to one worker together, so that it sets the scene up once.
  std::deque<std::vector<size_t>> batches;
  for (size_t position : positions) {
    if (batches.empty() ||
        plan.cases[batches.back().front()].scene_index != plan.cases[position].scene_index)
      batches.emplace_back();
    batches.back().push_back(position);
  }
  WorkerPool pool(o, plan, done);
  pool.run(std::move(batches), tick);
}

}  // namespace lt
