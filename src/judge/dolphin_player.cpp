#include "judge/dolphin_player.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/child_process.h"
#include "core/error.h"
#include "core/fs.h"
#include "judge/dolphin_config.h"
#include "judge/log_tail.h"
#include "judge/private_display.h"

namespace lt::judge {

namespace {

// What errors name as their "file": the judge, not one of the user's files.
constexpr const char* kWho = "dolphin";

// A temporary directory for one play, removed at the end unless LTRENDER_KEEP_DOLPHIN_DIR=1.
class SessionDir {
 public:
  SessionDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "ltrender-dolphin.XXXXXX");
    if (!::mkdtemp(pattern.data())) {
      throw InputError(
          kWho, "", "cannot create a temporary directory " + pattern + ": " + std::strerror(errno));
    }
    path_ = pattern;
  }
  ~SessionDir() {
    const char* keep = std::getenv(kKeepDolphinDirVariable);
    if (keep && std::string(keep) == "1") {
      std::fprintf(stderr, "ltrender: kept Dolphin's directory %s (%s=1)\n", path_.c_str(),
                   kKeepDolphinDirVariable);
      return;
    }
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  SessionDir(const SessionDir&) = delete;
  SessionDir& operator=(const SessionDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

std::filesystem::path require_executable(const std::string& name, const char* package) {
  const std::filesystem::path found = find_executable(name);
  if (found.empty()) {
    const bool searched = name.find('/') == std::string::npos;
    throw InputError(kWho, "",
                     name + " not found" + (searched ? " on PATH" : "") + " (Debian package " +
                         package + "; scripts/setup.sh installs it)");
  }
  return found;
}

// Where Dolphin's standard output and error go.
std::filesystem::path dolphin_output(const std::filesystem::path& session) {
  return session / "dolphin.out";
}

std::string seconds_text(double seconds) {
  std::ostringstream s;
  s << seconds << " s";
  return s.str();
}

// framedump_<n>.png in the order of n (framedump_10 after framedump_9).
std::vector<std::filesystem::path> dumped_frames(const std::filesystem::path& dir) {
  std::vector<std::pair<long, std::filesystem::path>> numbered;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string prefix = "framedump_", suffix = ".png";
    if (name.size() <= prefix.size() + suffix.size() || name.rfind(prefix, 0) != 0 ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    const std::string digits =
        name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
    if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9) continue;
    numbered.emplace_back(std::stol(digits), entry.path());
  }
  std::sort(numbered.begin(), numbered.end());
  std::vector<std::filesystem::path> out;
  for (auto& [n, path] : numbered) out.push_back(path);
  return out;
}

// "; its output ends: ..." from what Dolphin printed (alerts such as "DFF file magic number is
// incorrect" go there), else "; its log ends: ..." from its log file; empty if both are.
std::string what_dolphin_said(const std::filesystem::path& output,
                              const std::filesystem::path& log) {
  std::string tail = log_tail(output);
  if (!tail.empty()) return "; its output ends: " + tail;
  tail = log_tail(log);
  if (!tail.empty()) return "; its log ends: " + tail;
  return "";
}

std::string frames_so_far(std::size_t n) {
  return n == 0 ? "before dumping a frame"
                : "after dumping " + std::to_string(n) + (n == 1 ? " frame" : " frames");
}

// Dolphin runs `xdg-screensaver suspend` on its X11 window (whatever [Display]
// DisableScreenSaver says, in Debian's build); under Xvfb there is no screensaver and Debian's
// script fails loudly (no xset), burying Dolphin's own last words in the output we quote. A
// do-nothing xdg-screensaver first in its PATH keeps the output Dolphin's.
std::filesystem::path quiet_screensaver_dir(const std::filesystem::path& session) {
  const std::filesystem::path dir = session / "bin";
  std::filesystem::create_directories(dir);
  write_text_file(dir / "xdg-screensaver", "#!/bin/sh\nexit 0\n");
  std::filesystem::permissions(dir / "xdg-screensaver", std::filesystem::perms::owner_all |
                                                            std::filesystem::perms::group_read |
                                                            std::filesystem::perms::group_exec);
  return dir;
}

// What a play that is over gave: every frame dumped, or the InputError that says why none is
// to be trusted (the deadline, a failed or crashed Dolphin, no frame).
std::vector<Image> frames_or_why_not(bool ended, int status, const std::filesystem::path& session,
                                     const DolphinOptions& options) {
  const auto frames = dumped_frames(frame_dump_dir(session / "user"));
  const std::string said = what_dolphin_said(dolphin_output(session), log_file(session / "user"));
  if (!ended) {
    throw InputError(
        kWho, "",
        (frames.empty() ? "no frame dumped within " : "did not finish within ") +
            seconds_text(options.deadline_seconds) +
            (frames.empty() ? "" : " (" + std::to_string(frames.size()) + " frames dumped)") +
            said);
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError(kWho, "",
                     describe_wait_status(status) + " " + frames_so_far(frames.size()) + said);
  if (frames.empty()) {
    throw InputError(kWho, "",
                     "exited without dumping a frame (the last frame of a log is never shown: "
                     "it must hold its frame 3 times or more, see docs/dolphin-judge.md)" +
                         said);
  }
  std::vector<Image> images;
  for (const auto& frame : frames) images.push_back(read_image(frame));
  return images;
}

using PrepareLog = std::function<void(const std::filesystem::path& dff_in_session)>;

std::vector<Image> play(const PrepareLog& prepare_log, const DolphinOptions& options) {
  LT_CHECK(std::isfinite(options.deadline_seconds) && options.deadline_seconds > 0,
           "the Dolphin deadline is checked by the caller");
  LT_CHECK(std::isfinite(options.stop_grace_seconds) && options.stop_grace_seconds >= 0,
           "the grace after SIGINT is set by the caller");
  // Both before anything is made, so a missing program leaves nothing behind.
  const std::filesystem::path dolphin = require_executable(options.executable, "dolphin-emu");
  const std::filesystem::path xvfb = require_executable(options.xvfb, "xvfb");
  const auto deadline =
      ChildProcess::Clock::now() + std::chrono::duration_cast<ChildProcess::Clock::duration>(
                                       std::chrono::duration<double>(options.deadline_seconds));

  SessionDir session;
  const std::filesystem::path user = session.path() / "user";
  write_dolphin_user_dir(user);
  // Dolphin picks the boot type by the extension [DHW Boot.cpp GenerateFromFile ".dff"].
  const std::filesystem::path dff = session.path() / "frame.dff";
  prepare_log(dff);
  const std::vector<std::string> marker = {std::string(kDolphinSessionVariable) + "=" +
                                           session.path().string()};

  std::optional<PrivateDisplay> display;
  try {
    display.emplace(xvfb, session.path() / "xvfb.log", marker, deadline);
  } catch (const std::runtime_error& e) {
    throw InputError(kWho, "", e.what());
  }

  const std::filesystem::path output = dolphin_output(session.path());
  std::vector<std::string> environment = marker;
  environment.push_back("DISPLAY=" + display->name());
  environment.push_back("PATH=" + quiet_screensaver_dir(session.path()).string() + ":" +
                        (std::getenv("PATH") ? std::getenv("PATH") : "/usr/bin:/bin"));
  std::optional<ChildProcess> emulator;
  try {
    // -p x11: the software renderer needs a GL window (`-p headless` fails for it here).
    emulator.emplace(ChildProgram{
        dolphin,
        {"-u", user.string(), "-p", "x11", "-v", "Software Renderer", "-e", dff.string()},
        environment,
        output});
  } catch (const std::runtime_error& e) {
    throw InputError(kWho, "", e.what());
  }

  const bool ended = emulator->wait_until(deadline);
  emulator->stop(SIGINT, std::chrono::duration_cast<std::chrono::milliseconds>(
                             std::chrono::duration<double>(options.stop_grace_seconds)));
  display.reset();
  return frames_or_why_not(ended, emulator->wait_status(), session.path(), options);
}

}  // namespace

std::vector<Image> play_fifo_log(const std::filesystem::path& dff, const DolphinOptions& options) {
  // Dolphin opens it itself: refuse here what it would block on (a FIFO) or cannot read.
  std::error_code ec;
  if (!std::filesystem::exists(dff, ec)) throw InputError(dff.string(), "", "no such file");
  if (!std::filesystem::is_regular_file(dff, ec))
    throw InputError(dff.string(), "", "not a regular file (Dolphin plays a FIFO log file)");
  const std::filesystem::path target = std::filesystem::absolute(dff);
  return play(
      [&](const std::filesystem::path& in_session) {
        std::filesystem::create_symlink(target, in_session);
      },
      options);
}

std::vector<Image> play_fifo_log(const std::vector<std::uint8_t>& dff,
                                 const DolphinOptions& options) {
  return play([&](const std::filesystem::path& in_session) { write_binary_file(in_session, dff); },
              options);
}

bool dumped_unscaled(int width, int height) {
  return width > 0 && width % 16 == 0 && 3 * width == 4 * height;
}

}  // namespace lt::judge
