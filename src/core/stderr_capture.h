// Library diagnostics that bypass our error reporting. libpng's default error handler, which
// OpenImageIO 2.4 keeps, prints "libpng error: ..." straight to file descriptor 2 before
// OpenImageIO reports the same failure to us; cli.md allows exactly one stderr line. While such a
// library works for us, descriptor 2 goes to an anonymous file instead, and the caller folds what
// was written into its one error line, or passes it on unchanged when the call succeeds.
#pragma once

#include <mutex>
#include <string>
#include <vector>

namespace lt {

class StderrCapture {
 public:
  // Starts capturing. Captures are serialised process-wide (descriptor 2 is shared); if the
  // redirection cannot be set up, nothing is captured and stderr works as before.
  StderrCapture();
  // Stops capturing; text not taken with fold_into() is written to stderr as it was.
  ~StderrCapture();
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // `message` with the captured text appended in brackets unless the message already says it
  // (OpenImageIO usually repeats libpng's text): "cannot decode image: ... [libpng error: ...]".
  std::string fold_into(const std::string& message);

 private:
  void stop();
  std::vector<std::string> lines();  // stops, marks the text taken, splits it

  std::unique_lock<std::mutex> lock_;
  int saved_fd_ = -1;
  int capture_fd_ = -1;
  bool stopped_ = false;
  std::string text_;
  bool taken_ = false;
};

}  // namespace lt
