#include "core/stderr_capture.h"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <vector>

namespace lt {

namespace {

std::mutex& capture_mutex() {
  static std::mutex m;
  return m;
}

// A library that fails in a loop could write without end: keep the start, which names the
// failure.
constexpr std::size_t kMaxCaptured = 1 << 16;

std::string trim(const std::string& s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return "";
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

}  // namespace

StderrCapture::StderrCapture() : lock_(capture_mutex()) {
  std::fflush(stderr);
  std::cerr.flush();
  capture_fd_ = ::memfd_create("ltrender-stderr", MFD_CLOEXEC);
  if (capture_fd_ < 0) return;
  saved_fd_ = ::dup(STDERR_FILENO);
  if (saved_fd_ < 0 || ::dup2(capture_fd_, STDERR_FILENO) < 0) {
    if (saved_fd_ >= 0) ::close(saved_fd_);
    ::close(capture_fd_);
    saved_fd_ = capture_fd_ = -1;
  }
}

StderrCapture::~StderrCapture() {
  stop();
  if (!taken_ && !text_.empty()) {
    std::fwrite(text_.data(), 1, text_.size(), stderr);
    std::fflush(stderr);
  }
}

void StderrCapture::stop() {
  if (stopped_) return;
  stopped_ = true;
  if (capture_fd_ < 0) return;
  std::fflush(stderr);
  std::cerr.flush();
  ::dup2(saved_fd_, STDERR_FILENO);
  ::close(saved_fd_);
  std::vector<char> buf(kMaxCaptured);
  const ssize_t n = ::pread(capture_fd_, buf.data(), buf.size(), 0);
  if (n > 0) text_.assign(buf.data(), static_cast<std::size_t>(n));
  ::close(capture_fd_);
}

std::vector<std::string> StderrCapture::lines() {
  stop();
  taken_ = true;
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start < text_.size()) {
    std::size_t end = text_.find('\n', start);
    if (end == std::string::npos) end = text_.size();
    std::string line = trim(text_.substr(start, end - start));
    if (!line.empty()) out.push_back(std::move(line));
    start = end + 1;
  }
  return out;
}

std::string StderrCapture::fold_into(const std::string& message) {
  std::string extra;
  for (const auto& line : lines()) {
    // libpng prefixes its text ("libpng error: IDAT: ..."); OpenImageIO repeats what follows.
    const auto colon = line.find(": ");
    const std::string core = colon == std::string::npos ? line : line.substr(colon + 2);
    if (message.find(core) != std::string::npos) continue;
    extra += (extra.empty() ? "" : "; ") + line;
  }
  return extra.empty() ? message : message + " [" + extra + "]";
}

}  // namespace lt
