// The worker's side of regress_workers.h.
#include <unistd.h>

#include <cerrno>
#include <optional>
#include <stdexcept>

#include "core/fs.h"
#include "regress/case_record.h"
#include "regress/regress_workers.h"
#include "regress/run_case.h"
#include "regress/test_hook.h"

namespace lt {

namespace {

void send_line(int fd, const std::string& text) {
  const std::string line = text + "\n";
  for (size_t sent = 0; sent < line.size();) {
    const ssize_t n = ::write(fd, line.data() + sent, line.size() - sent);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw std::runtime_error("regress worker: the parent's socket is closed");
    sent += static_cast<size_t>(n);
  }
}

// The next line from the parent; false at the end (the parent closed the socket).
bool read_line(int fd, std::string& buffer, std::string& line) {
  for (;;) {
    const size_t end = buffer.find('\n');
    if (end != std::string::npos) {
      line = buffer.substr(0, end);
      buffer.erase(0, end + 1);
      return true;
    }
    char chunk[4096];
    const ssize_t n = ::read(fd, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    buffer.append(chunk, static_cast<size_t>(n));
  }
}

// One batch: the named cases of one scene, in one session (one GL context), as a run in one
// process renders them.
void run_batch(const RegressOptions& o, const std::vector<fs::path>& scene_files,
               const std::vector<PathRequest>& requests, const nlohmann::json& batch, int fd) {
  const size_t s = batch.at("scene").get<size_t>();
  const fs::path& file = scene_files.at(s);
  const Scene scene = load_scene(file, o.scene_options);
  std::vector<RegressCase> cases = expand_cases({file}, {scene}, requests);
  std::optional<RenderSession> session;
  for (const auto& id : batch.at("cases")) {
    const RegressCase* c = nullptr;
    for (RegressCase& candidate : cases) {
      candidate.scene_index = s;
      if (candidate.id() == id.get<std::string>()) c = &candidate;
    }
    if (!c) throw std::runtime_error("regress worker: no case " + id.get<std::string>());
    send_line(fd, nlohmann::json{{"started", c->id()}}.dump());
    run_regress_test_hook(c->id());
    if (!session) {
      session.emplace(scene, o.width > 0 ? o.width : scene.width,
                      o.height > 0 ? o.height : scene.height);
    }
    send_line(fd, nlohmann::json{{"result", case_record(run_case(o, file, *session, *c))}}.dump());
  }
}

}  // namespace

int run_regress_worker(const RegressOptions& o, int fd) {
  const std::vector<fs::path> scene_files = collect_scene_files(o.inputs);
  const std::vector<PathRequest> requests = parse_path_list(o.paths);
  std::string buffer, line;
  while (read_line(fd, buffer, line))
    run_batch(o, scene_files, requests, nlohmann::json::parse(line), fd);
  return 0;
}

}  // namespace lt
