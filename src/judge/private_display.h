// An X server of our own (Xvfb) for a program that needs a display where there is no screen:
// Dolphin's software renderer draws through GL in an X11 window (`-p headless` fails for it in
// Debian's build, which has no EGL). Xvfb picks a free display number itself and tells us
// through -displayfd, so two plays at once never race for one.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "core/child_process.h"

namespace lt::judge {

class PrivateDisplay {
 public:
  // Starts `xvfb` (an executable path) with its output in `log`, and waits until it is ready.
  // Throws std::runtime_error when it cannot start, ends first, or is not ready by `deadline`
  // (the message quotes the end of its output).
  PrivateDisplay(const std::filesystem::path& xvfb, const std::filesystem::path& log,
                 const std::vector<std::string>& environment_additions,
                 ChildProcess::Clock::time_point deadline);
  // Stops the server: SIGTERM, its clean end (it removes its lock file), then SIGKILL.
  ~PrivateDisplay();

  // The DISPLAY value, e.g. ":1".
  const std::string& name() const { return name_; }

 private:
  std::unique_ptr<ChildProcess> server_;
  std::string name_;
};

}  // namespace lt::judge
