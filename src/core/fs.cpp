#include "core/fs.h"

#include <unistd.h>

#include <fstream>
#include <sstream>

#include "core/error.h"

namespace lt {

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw InputError(target.string(), "", "output directory does not exist");
  }
  // Same directory as the target so the final rename is atomic (no cross-device copy).
  // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on a chained operator+ starting "." +.
  std::string name = ".";
  name.append(target.stem().string())
      .append(".tmp.")
      .append(std::to_string(::getpid()))
      .append(target.extension().string());
  const fs::path tmp = dir / name;
  try {
    write(tmp);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, target, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw InputError(target.string(), "", "cannot write output: " + ec.message());
  }
}

void ensure_not_an_input(const fs::path& output, const std::vector<fs::path>& inputs) {
  std::error_code ec;
  for (const auto& in : inputs) {
    if (fs::exists(output, ec) && fs::equivalent(output, in, ec)) {
      throw InputError(output.string(), "", "output would overwrite an input file");
    }
  }
}

std::string read_text_file(const fs::path& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw InputError(path.string(), "", "file not found");
  if (fs::is_directory(path, ec)) throw InputError(path.string(), "", "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string(), "", "cannot open file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace lt
