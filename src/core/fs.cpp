#include "core/fs.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <new>
#include <vector>

#include "core/error.h"
#include "core/fixed.h"

namespace lt {

namespace {

// ".<target's name>.ltrender-partial.": what every temporary of `target` starts with.
std::string partial_prefix(const fs::path& target) {
  std::string prefix = ".";
  prefix.append(target.filename().string()).append(kPartialOutputTag);
  return prefix;
}

// The pid in a temporary's name when it is one of `target`'s, else 0.
long partial_pid(const std::string& name, const fs::path& target) {
  const std::string prefix = partial_prefix(target), ext = target.extension().string();
  if (name.size() <= prefix.size() + ext.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - ext.size(), ext.size(), ext) != 0) {
    return 0;
  }
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - ext.size());
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != digits.npos)
    return 0;
  return std::stol(digits);
}

// A process we may not signal (EPERM) is alive too: only ESRCH says it is gone.
bool process_is_gone(long pid) {
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

// A write killed before its rename leaves its temporary behind, and nothing else would ever
// remove it: the next write of the same target removes those whose process is gone. Only
// entries with exactly our name pattern and of the kind we write (a regular file, or for
// write_directory_atomically a directory) are touched, never through a symlink.
void remove_stale_partials(const fs::path& dir, const fs::path& target, bool directories = false) {
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const long pid = partial_pid(it->path().filename().string(), target);
    if (pid <= 0 || pid == ::getpid() || it->is_symlink(ec)) continue;
    if (directories ? !it->is_directory(ec) : !it->is_regular_file(ec)) continue;
    if (process_is_gone(pid)) stale.push_back(it->path());
  }
  for (const auto& p : stale) fs::remove_all(p, ec);
}

}  // namespace

fs::path partial_output_path(const fs::path& target, long pid) {
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  std::string name = partial_prefix(target);
  name.append(std::to_string(pid)).append(target.extension().string());
  return dir / name;
}

void write_atomically(const fs::path& target, const std::function<void(const fs::path&)>& write) {
  fs::path dir = target.parent_path();
  if (dir.empty()) dir = ".";
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    throw InputError(target.string(), "", "output directory does not exist");
  }
  remove_stale_partials(dir, target);
  // Same directory as the target so the final rename is atomic (no cross-device copy).
  const fs::path tmp = partial_output_path(target, ::getpid());
  try {
    write(tmp);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  std::error_code renamed;
  fs::rename(tmp, target, renamed);
  if (renamed) {
    fs::remove(tmp, ec);  // its own code: `renamed` is the reason the user needs
    throw InputError(target.string(), "", "cannot write output: " + renamed.message());
  }
}

void write_directory_atomically(const fs::path& dir,
                                const std::function<void(const fs::path& staging)>& write) {
  const fs::path target = dir.filename().empty() ? dir.parent_path() : dir;  // "out/" is out
  fs::path parent = target.parent_path();
  if (parent.empty()) parent = ".";
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) {
    throw InputError(dir.string(), "", "the output directory's parent does not exist");
  }
  if (fs::exists(target, ec) && !fs::is_directory(target, ec)) {
    throw InputError(dir.string(), "", "exists and is not a directory");
  }
  remove_stale_partials(parent, target, /*directories=*/true);
  const fs::path staging = partial_output_path(target, ::getpid());
  fs::remove_all(staging, ec);
  if (!fs::create_directory(staging, ec) || ec) {
    throw InputError(dir.string(), "", "cannot create a staging directory: " + ec.message());
  }
  try {
    write(staging);
  } catch (...) {
    fs::remove_all(staging, ec);
    throw;
  }
  // Publish: directories first, then each file by rename (same filesystem, as the staging
  // directory is a sibling of the target).
  std::error_code moved;
  fs::create_directories(target, moved);
  for (fs::recursive_directory_iterator it(staging, ec), end; !moved && !ec && it != end;
       it.increment(ec)) {
    const fs::path to = target / fs::relative(it->path(), staging);
    if (it->is_directory()) {
      fs::create_directories(to, moved);
    } else {
      fs::rename(it->path(), to, moved);
    }
  }
  fs::remove_all(staging, ec);
  if (moved) throw InputError(dir.string(), "", "cannot write output: " + moved.message());
}

namespace {

void write_chars(const fs::path& target, const char* data, std::size_t size) {
  write_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out.write(data, static_cast<std::streamsize>(size));
    out.close();
    if (!out) throw InputError(target.string(), "", "cannot write");
  });
}

}  // namespace

void write_text_file(const fs::path& target, const std::string& text) {
  write_chars(target, text.data(), text.size());
}

void write_binary_file(const fs::path& target, std::span<const std::uint8_t> bytes) {
  write_chars(target, reinterpret_cast<const char*>(bytes.data()), bytes.size());
}

void ensure_not_an_input(const fs::path& output, const std::vector<fs::path>& inputs) {
  std::error_code ec;
  for (const auto& in : inputs) {
    if (fs::exists(output, ec) && fs::equivalent(output, in, ec)) {
      throw InputError(output.string(), "", "output would overwrite an input file");
    }
  }
}

namespace {

constexpr std::uintmax_t kMiB = std::uintmax_t{1} << 20;

const char* kind_noun(InputKind kind) {
  switch (kind) {
    case InputKind::Scene:
      return "scene file";
    case InputKind::Mesh:
      return "mesh file";
    case InputKind::Image:
      return "image file";
    case InputKind::Program:
      return "program file";
    case InputKind::Gltf:
      return "glTF file";
  }
  return "file";
}

std::string size_text(std::uintmax_t bytes) {
  if (bytes < kMiB) return std::to_string(bytes) + " bytes";
  return fixed(static_cast<double>(bytes) / static_cast<double>(kMiB), 1, " MiB");
}

[[noreturn]] void refuse(const fs::path& path, const std::string& what) {
  throw InputError(path.string(), "", what);
}

[[noreturn]] void refuse_size(const fs::path& path, InputKind kind, std::uintmax_t size) {
  refuse(path, "is " + size_text(size) + ", over the " +
                   std::to_string(input_size_cap(kind) / kMiB) + " MiB limit for " +
                   kind_noun(kind) + "s");
}

// Why a file that is not regular is refused, in the words of `ls -l`; through a symlink (a
// scene linked to /dev/zero), the link's target too.
std::string not_regular(const fs::path& path, mode_t mode, InputKind kind) {
  std::string what;
  if (S_ISDIR(mode)) {
    what = std::string("is a directory, not ") + (kind == InputKind::Image ? "an " : "a ") +
           kind_noun(kind);
  } else if (S_ISFIFO(mode)) {
    what = "is a FIFO (named pipe), not a regular file";
  } else if (S_ISCHR(mode)) {
    what = "is a character device, not a regular file";
  } else if (S_ISBLK(mode)) {
    what = "is a block device, not a regular file";
  } else if (S_ISSOCK(mode)) {
    what = "is a socket, not a regular file";
  } else {
    what = "is not a regular file";
  }
  std::error_code ec;
  if (fs::is_symlink(path, ec)) {
    const fs::path target = fs::read_symlink(path, ec);
    if (!ec) what += " (a symbolic link to " + target.string() + ")";
  }
  return what;
}

void check_stat(const fs::path& path, const struct stat& st, InputKind kind) {
  if (!S_ISREG(st.st_mode)) refuse(path, not_regular(path, st.st_mode, kind));
  const auto size = static_cast<std::uintmax_t>(st.st_size);
  if (size > input_size_cap(kind)) refuse_size(path, kind, size);
}

struct FdCloser {
  int fd;
  ~FdCloser() { ::close(fd); }
};

}  // namespace

std::uintmax_t input_size_cap(InputKind kind) {
  switch (kind) {
    case InputKind::Scene:
    case InputKind::Program:
      return 16 * kMiB;
    case InputKind::Mesh:
    case InputKind::Gltf:  // a .glb holds its meshes: the mesh cap
      return 256 * kMiB;
    case InputKind::Image:
      return 512 * kMiB;
  }
  return 16 * kMiB;
}

std::uintmax_t check_input_file(const fs::path& path, InputKind kind) {
  // The system calls stop at a NUL: the file checked would not be the file named.
  if (path.native().find('\0') != std::string::npos) refuse(path, "path contains a NUL byte");
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) {
    const int err = errno;
    if (err == ENOENT || err == ENOTDIR) refuse(path, "file not found");
    refuse(path, std::string("cannot open file: ") + std::strerror(err));
  }
  check_stat(path, st, kind);
  return static_cast<std::uintmax_t>(st.st_size);
}

std::string read_input_file(const fs::path& path, InputKind kind) {
  check_input_file(path, kind);
  // O_NONBLOCK: should a FIFO be swapped in after the check, open() still returns at once, and
  // fstat below refuses it.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) refuse(path, std::string("cannot open file: ") + std::strerror(errno));
  const FdCloser closer{fd};
  struct stat st {};
  if (::fstat(fd, &st) != 0) refuse(path, std::string("cannot read file: ") + std::strerror(errno));
  check_stat(path, st, kind);
  const std::uintmax_t cap = input_size_cap(kind);
  std::string data;
  try {
    data.reserve(static_cast<std::size_t>(st.st_size));
    char buf[1 << 16];
    for (;;) {
      const ssize_t n = ::read(fd, buf, sizeof buf);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) refuse(path, std::string("cannot read file: ") + std::strerror(errno));
      if (n == 0) break;
      data.append(buf, static_cast<std::size_t>(n));
      if (data.size() > cap) refuse_size(path, kind, data.size());
    }
  } catch (const std::bad_alloc&) {
    refuse(path, "out of memory reading " + size_text(static_cast<std::uintmax_t>(st.st_size)));
  }
  return data;
}

std::string read_text_file(const fs::path& path) {
  return read_input_file(path, InputKind::Program);
}

}  // namespace lt
