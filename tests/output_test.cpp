// Writing outputs (core/fs.h write_atomically): a temporary beside the target, then a rename; a
// failure is cli.md's one line with the real reason, and leaves nothing behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "core/fs.h"
#include "test_util.h"

namespace lt {
namespace {

namespace fs = std::filesystem;

const char* kScene = R"({
  "image": {"width": 16, "height": 12},
  "camera": {"eye": [0, 0, 4], "target": [0, 0, 0]},
  "materials": {"m": {"albedo": [0.8, 0.8, 0.8]}},
  "lights": [{"type": "directional", "direction": [0, 0, 1]}],
  "objects": [{"mesh": "quad.obj", "material": "m"}]
})";

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// The rename's error code was overwritten by the clean-up's before it was printed:
// "cannot write output: Success".
TEST(WriteAtomically, AnOutputThatIsADirectoryGivesTheRenamesReason) {
  test::TempDir dir;
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "s.json", kScene);
  fs::create_directory(dir / "out.png");
  const auto r = test::run_ltrender("render " + (dir / "s.json").string() + " --path flat -o " +
                                    (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(r.err, "ltrender: error: " + (dir / "out.png").string() +
                       ": cannot write output: Is a directory\n");
  EXPECT_TRUE(fs::is_directory(dir / "out.png"));
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out.png", "quad.obj", "s.json"}));

  try {
    write_atomically(dir / "out.png", [](const fs::path& tmp) { test::write_file(tmp, "x"); });
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.what_only(), "cannot write output: Is a directory");
  }
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"out.png", "quad.obj", "s.json"}));
}

TEST(WriteAtomically, TheTemporarySaysWhatItIs) {
  test::TempDir dir;
  fs::path seen;
  write_atomically(dir / "out.png", [&](const fs::path& tmp) {
    seen = tmp;
    test::write_file(tmp, "x");
  });
  EXPECT_EQ(seen, dir / (".out.png.ltrender-partial." + std::to_string(::getpid()) + ".png"));
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"out.png"});
}

// A pid that was a process a moment ago and is none now.
long gone_pid() {
  const pid_t pid = ::fork();
  if (pid == 0) ::_exit(0);
  ::waitpid(pid, nullptr, 0);
  return pid;
}

// A killed write leaves its temporary; nothing removed them. The next write of the same target
// removes those of gone processes, and nothing else.
TEST(WriteAtomically, StaleTemporariesOfGoneProcessesGoOnTheNextWrite) {
  test::TempDir dir;
  const long gone = gone_pid();
  const fs::path stale = partial_output_path(dir / "out.png", gone);
  const fs::path alive = partial_output_path(dir / "out.png", ::getppid());  // a live writer's
  const fs::path other = partial_output_path(dir / "other.png", gone);       // another target's
  const fs::path dir_like = partial_output_path(dir / "out.png", gone + 1);  // not a file
  for (const auto& p : {stale, alive, other}) test::write_file(p, "partial");
  fs::create_directory(dir_like);
  write_atomically(dir / "out.png", [](const fs::path& tmp) { test::write_file(tmp, "x"); });
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_TRUE(fs::exists(other));
  EXPECT_TRUE(fs::is_directory(dir_like));

  // Through the command line too.
  test::write_file(stale, "partial");
  test::write_file(dir / "quad.obj", test::quad_obj());
  test::write_file(dir / "s.json", kScene);
  const auto r = test::run_ltrender("render " + (dir / "s.json").string() + " --path flat -o " +
                                    (dir / "out.png").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(stale));
}

}  // namespace
}  // namespace lt
