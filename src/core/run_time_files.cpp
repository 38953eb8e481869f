#include "core/run_time_files.h"

#include <system_error>

#include "core/build_paths.h"
#include "core/install_layout.h"

namespace lt::run_time_files {

std::filesystem::path executable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path() : exe;
}

bool from_build_tree() {
  // equivalent() fails (false) where the build directory does not exist: another machine.
  std::error_code ec;
  return std::filesystem::equivalent(executable().parent_path(), build_paths::binary_dir(), ec);
}

std::filesystem::path data_dir() {
  if (from_build_tree()) return build_paths::source_dir();
  return (executable().parent_path() / install_layout::data_dir_from_bin()).lexically_normal();
}

std::filesystem::path module_dir() {
  if (from_build_tree()) return build_paths::binary_dir();
  return (executable().parent_path() / install_layout::module_dir_from_bin()).lexically_normal();
}

}  // namespace lt::run_time_files
