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

namespace lt {
namespace {

// write_directory_atomically: all files or none, and a killed writer's staging directory goes
// on the next write.
TEST(WriteDirectoryAtomically, PublishesEveryFileOrNone) {
  test::TempDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(out);
  test::write_file(out / "report.md", "old");
  EXPECT_THROW(write_directory_atomically(out,
                                          [](const fs::path& staging) {
                                            test::write_file(staging / "report.md", "new");
                                            throw InputError("x", "", "failed halfway");
                                          }),
               InputError);
  EXPECT_EQ(test::read_file(out / "report.md"), "old");
  EXPECT_FALSE(fs::exists(partial_output_path(out, ::getpid())));

  write_directory_atomically(out, [](const fs::path& staging) {
    fs::create_directories(staging / "images");
    test::write_file(staging / "images" / "a.png", "a");
    test::write_file(staging / "report.md", "new");
  });
  EXPECT_EQ(test::read_file(out / "report.md"), "new");
  EXPECT_EQ(test::read_file(out / "images" / "a.png"), "a");
  EXPECT_FALSE(fs::exists(partial_output_path(out, ::getpid())));

  const fs::path stale = partial_output_path(out, gone_pid());
  fs::create_directories(stale / "images");
  test::write_file(stale / "images" / "b.png", "b");
  write_directory_atomically(out, [](const fs::path&) {});
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_FALSE(fs::exists(out / "images" / "b.png"));
}

// Issue 15: a killed bench left a directory of new images beside an old report.md.
TEST(WriteDirectoryAtomically, AKilledBenchLeavesThePreviousRunAsItWas) {
  test::TempDir dir;
  const fs::path out = dir / "out";
  fs::create_directories(out);
  test::write_file(out / "report.md", "old");
  const std::string scene = (test::source_dir() / "scenes" / "backlit_sphere.json").string();
  // Far longer than 3 s (every path and variant, 200 frames each), so the kill lands mid-run.
  const auto killed =
      test::run_ltrender("bench " + scene + " --frames 200 --quiet -o " + out.string(), {3, 0});
  ASSERT_NE(killed.exit_code, 0) << "the bench finished before it was killed";
  EXPECT_EQ(test::read_file(out / "report.md"), "old");
  EXPECT_FALSE(fs::exists(out / "images"));

  const auto again =
      test::run_ltrender("bench " + scene + " --paths flat --frames 10 --quiet -o " + out.string());
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_NE(test::read_file(out / "report.md"), "old");
  EXPECT_TRUE(fs::exists(out / "images"));
  for (const auto& e : fs::directory_iterator(dir.path()))
    EXPECT_EQ(e.path().filename().string().find(kPartialOutputTag), std::string::npos)
        << e.path() << " is a staging directory left behind";
}

}  // namespace
}  // namespace lt
