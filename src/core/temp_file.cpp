#include "core/temp_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdlib>

namespace lt {

TempFile::TempFile(const std::string& what, const std::string& extension, const void* data,
                   std::size_t size) {
  // mkstemps: a name no other process holds, created 0600 and exclusively (no symlink planted in
  // the shared temporary folder can redirect the write).
  std::string pattern =
      (std::filesystem::temp_directory_path() / ("ltrender-" + what + ".XXXXXX" + extension))
          .string();
  const int fd = ::mkstemps(pattern.data(), static_cast<int>(extension.size()));
  if (fd < 0) return;
  path_ = pattern;
  const char* p = static_cast<const char*>(data);
  std::size_t left = size;
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n <= 0) break;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  written_ = ::close(fd) == 0 && left == 0;
}

TempFile::~TempFile() {
  std::error_code ec;
  if (!path_.empty()) std::filesystem::remove(path_, ec);
}

}  // namespace lt
