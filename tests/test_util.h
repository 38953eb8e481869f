// Shared helpers for tests: temporary directories, running the CLI, small scenes.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/build_paths.h"
#include "image/image.h"

namespace lt {
namespace fs = std::filesystem;  // the same alias as core/fs.h
}  // namespace lt

namespace lt::test {

namespace fs = std::filesystem;

// A fresh directory under the system temp dir, removed at scope exit.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() /
            ("lt_" + std::string(info ? info->test_suite_name() : "t") + "_" +
             std::string(info ? info->name() : "t") + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }
  fs::path operator/(const std::string& name) const { return path_ / name; }

 private:
  fs::path path_;
};

inline std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// How many lines `s` holds (a one-line error message is 1).
inline int count_lines(const std::string& s) {
  return static_cast<int>(std::count(s.begin(), s.end(), '\n'));
}

inline void write_file(const fs::path& p, const std::string& text) {
  std::ofstream out(p, std::ios::binary);
  out << text;
}

struct RunResult {
  int exit_code;
  std::string out, err;
};

// Built by ./test.sh --sanitize (AddressSanitizer): its shadow memory cannot live under
// `ulimit -v`, and its allocator exits on exhaustion instead of throwing std::bad_alloc.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

// Bounds for a run that must not hang or exhaust memory when the bug it tests is back: a hang
// ends as exit 124 (timeout(1)), runaway memory as a failed allocation (in a sanitized build,
// AddressSanitizer's own RSS limit ends it).
struct RunLimits {
  int seconds = 0;          // 0: no time limit
  long long memory_mb = 0;  // address space (ulimit -v); 0: no limit
};

// Runs the built ltrender binary with `args` (a shell-quoted string).
inline RunResult run_ltrender(const std::string& args, const RunLimits& limits = {}) {
  const fs::path dir = fs::temp_directory_path();
  const std::string tag = std::to_string(::getpid()) + "_" + std::to_string(std::rand());
  const fs::path out = dir / ("lt_out_" + tag), err = dir / ("lt_err_" + tag);
  std::string prefix;
  if (limits.memory_mb > 0 && kSanitizedBuild) {
    prefix += "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}hard_rss_limit_mb=" +
              std::to_string(limits.memory_mb) + " ";
  } else if (limits.memory_mb > 0) {
    prefix += "ulimit -v " + std::to_string(limits.memory_mb * 1024) + "; ";
  }
  if (limits.seconds > 0) prefix += "timeout -k 5 " + std::to_string(limits.seconds) + " ";
  const std::string cmd = prefix + lt::build_paths::ltrender_binary().string() + " " + args + " >" +
                          out.string() + " 2>" + err.string();
  const int status = std::system(cmd.c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  RunResult r{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), slurp(out),
              slurp(err)};
  fs::remove(out);
  fs::remove(err);
  return r;
}

// Standard output of a shell command and its exit code (the repo's scripts, run by their tests).
struct CommandOutput {
  int exit_code = -1;
  std::string out;
};
inline CommandOutput command_output(const std::string& command) {
  CommandOutput r;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[4096];
  while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.out.append(buffer, n);
  const int status = pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

// A unit quad in the XY plane facing +Z (two triangles), as OBJ with explicit normals.
inline std::string quad_obj() {
  return "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\n"
         "vn 0 0 1\n"
         "f 1//1 2//1 3//1\nf 1//1 3//1 4//1\n";
}

inline const fs::path source_dir() {
  return lt::build_paths::source_dir();
}

// The .json files of a folder of the source tree (e.g. "scenes/hard"), as "folder/name.json",
// sorted, so parameterised tests pick up every scene without a list to keep in step.
inline std::vector<std::string> json_files(const std::string& sub) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(source_dir() / sub)) {
    if (e.path().extension() == ".json") {
      out.push_back((fs::path(sub) / e.path().filename()).string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

// A gtest parameter name: anything but letters and digits becomes _.
inline std::string test_param_name(const std::string& s) {
  std::string r = s;
  for (char& c : r) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return r;
}

// A scene file's gtest parameter name: its stem, anything but letters and digits as _.
inline std::string scene_param_name(const std::string& file) {
  return test_param_name(fs::path(file).stem().string());
}

// `text` with every `from` replaced by `to` (each must occur): a program file edited as a user
// would edit it.
inline std::string with_edits(std::string text,
                              const std::vector<std::pair<std::string, std::string>>& edits) {
  for (const auto& [from, to] : edits) {
    size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    for (; at != std::string::npos; at = text.find(from, at + to.size()))
      text.replace(at, from.size(), to);
  }
  return text;
}

// The line (1-based) of the first occurrence of `needle` in `text`.
inline int line_holding(const std::string& text, const std::string& needle) {
  const size_t at = text.find(needle);
  EXPECT_NE(at, std::string::npos) << needle;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

// The helpers below walk every pixel. They are compiled optimised in tests/test_pixels.cpp, not
// inline here: the test binaries are built at -O0 (cmake/test_binaries.cmake), where non_finite's
// loop of std::isfinite calls and vector iterators was ~10% of Demo/Bounded's CPU (`perf`), ~1%
// optimised.

// NaN or Inf values anywhere in an image (all four channels): model.md's "no NaN or Inf ever
// reaches an image" is this being 0.
size_t non_finite(const Image& img);

// Pixels whose alpha (coverage) is over one half.
size_t covered_pixels(const Image& img);

// Pixels whose 8-bit RGB differ between two pictures of one size, and the largest difference.
struct PictureDifference {
  size_t differ = 0;
  int max = 0;
  int first_x = -1, first_y = -1;
};
PictureDifference picture_difference(const Image& a, const Image& b);

}  // namespace lt::test
