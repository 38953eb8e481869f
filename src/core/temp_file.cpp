#include "core/temp_file.h"

#include <unistd.h>

#include <atomic>
#include <fstream>

namespace lt {

TempFile::TempFile(const std::string& what, const std::string& extension, const void* data,
                   std::size_t size) {
  // The process id and a counter: concurrent commands and threads never share a name.
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("ltrender-" + what + "." + std::to_string(getpid()) + "." + std::to_string(counter++) +
           extension);
  std::ofstream out(path_, std::ios::binary);
  out.write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  written_ = static_cast<bool>(out);
}

TempFile::~TempFile() {
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace lt
