// judge/dolphin_player: how a play of a FIFO log fails (one line, nothing left running, no
// directory left), where its frames come from, and `render --via dolphin`'s refusals. Playing a
// real frame needs a FIFO log encoder (the gx path's fifo_log); that end-to-end case lives with
// the encoder. The stand-ins for Dolphin here are shell scripts: they hang, crash, ignore
// SIGINT, leave a child behind, or dump frames, which Dolphin cannot be made to do on purpose.
#include "judge/dolphin_player.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

#include "core/child_process.h"
#include "core/error.h"
#include "image/image.h"
#include "judge/log_tail.h"
#include "test_util.h"

namespace lt {
namespace {

using judge::DolphinOptions;
using judge::play_fifo_log;
using test::TempDir;
using Clock = std::chrono::steady_clock;

// A scratch directory that is also TMPDIR while the test runs, so every session directory a
// play makes is inside it and the test can see whether one was left.
class Scratch {
 public:
  Scratch() : tmp_(dir_ / "tmp") {
    std::filesystem::create_directories(tmp_);
    const char* old = std::getenv("TMPDIR");
    had_old_ = old != nullptr;
    if (had_old_) old_ = old;
    ::setenv("TMPDIR", tmp_.c_str(), 1);
  }
  ~Scratch() {
    if (had_old_) {
      ::setenv("TMPDIR", old_.c_str(), 1);
    } else {
      ::unsetenv("TMPDIR");
    }
  }
  std::filesystem::path operator/(const std::string& name) const { return dir_ / name; }
  const std::filesystem::path& tmp() const { return tmp_; }
  bool tmp_is_empty() const { return std::filesystem::is_empty(tmp_); }

 private:
  TempDir dir_;
  std::filesystem::path tmp_;
  bool had_old_ = false;
  std::string old_;
};

// Processes whose environment carries a session variable under `tmp` (every process a play
// started, and whatever they started in turn). Zombies have no environment left to read.
std::vector<std::string> processes_of_sessions_in(const std::filesystem::path& tmp) {
  const std::string marker = std::string(judge::kDolphinSessionVariable) + "=" + tmp.string() + "/";
  std::vector<std::string> found;
  for (const auto& entry : std::filesystem::directory_iterator("/proc")) {
    const std::string pid = entry.path().filename().string();
    if (pid.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream in(entry.path() / "environ", std::ios::binary);
    std::string variable;
    while (std::getline(in, variable, '\0')) {
      if (variable.rfind(marker, 0) == 0) found.push_back(pid);
    }
  }
  return found;
}

void write_script(const std::filesystem::path& path, const std::string& body) {
  test::write_file(path, "#!/bin/sh\n" + body);
  ::chmod(path.c_str(), 0755);
}

// The message of the InputError `play` throws; fails the test if it throws none.
template <typename Play>
std::string input_error_of(Play play) {
  try {
    play();
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no InputError";
  return "";
}

bool real_tools_present() {
  return !find_executable(DolphinOptions{}.executable).empty() &&
         !find_executable(DolphinOptions{}.xvfb).empty();
}
#define SKIP_WITHOUT_DOLPHIN()                                                             \
  if (!real_tools_present())                                                               \
  GTEST_SKIP() << "dolphin-emu-nogui or Xvfb missing (Debian packages dolphin-emu, xvfb; " \
                  "scripts/setup.sh installs them)"

// A log is only a name here: the stand-ins never read it.
std::vector<std::uint8_t> some_bytes() {
  return std::vector<std::uint8_t>(64, 0x5a);
}

// A play by a stand-in for Dolphin (a shell script) that must fail: its one line, and how long
// it took.
struct FailedPlay {
  std::string what;
  Clock::duration took;
};
FailedPlay failed_play(const DolphinOptions& options) {
  const auto start = Clock::now();
  const std::string what = input_error_of([&] { play_fifo_log(some_bytes(), options); });
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  return {what, Clock::now() - start};
}

// Options whose Dolphin (or, with `program` "xvfb", whose X server) is a script in `scratch`.
DolphinOptions stand_in(const Scratch& scratch, const std::string& program,
                        const std::string& script, double deadline) {
  DolphinOptions options;
  options.executable = (scratch / "dolphin").string();
  write_script(options.executable, program == "dolphin" ? script : "exit 0\n");
  if (program == "xvfb") {
    options.xvfb = (scratch / "xvfb").string();
    write_script(options.xvfb, script);
  }
  options.deadline_seconds = deadline;
  return options;
}

FailedPlay play_stand_in(const Scratch& scratch, const std::string& script, double deadline) {
  return failed_play(stand_in(scratch, "dolphin", script, deadline));
}

// No process of a play is running (whatever started it) and no session directory is left.
void expect_nothing_left(const Scratch& scratch) {
  EXPECT_TRUE(processes_of_sessions_in(scratch.tmp()).empty());
  EXPECT_TRUE(scratch.tmp_is_empty());
}

TEST(DolphinPlayer, MissingDolphinIsOneLineNamingItsPathAndPackage) {
  Scratch scratch;
  DolphinOptions options;
  options.executable = (scratch / "no-such-dolphin-emu-nogui").string();
  const std::string what = input_error_of([&] { play_fifo_log(some_bytes(), options); });
  EXPECT_NE(what.find(options.executable + " not found"), std::string::npos) << what;
  EXPECT_NE(what.find("Debian package dolphin-emu"), std::string::npos) << what;
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  EXPECT_TRUE(scratch.tmp_is_empty());
}

TEST(DolphinPlayer, MissingXvfbIsOneLineNamingItAndItsPackage) {
  Scratch scratch;
  DolphinOptions options;
  options.executable = (scratch / "dolphin").string();
  write_script(options.executable, "exit 0\n");
  options.xvfb = "ltrender-test-no-such-xvfb";
  const std::string what = input_error_of([&] { play_fifo_log(some_bytes(), options); });
  EXPECT_NE(what.find("ltrender-test-no-such-xvfb not found on PATH (Debian package xvfb"),
            std::string::npos)
      << what;
  EXPECT_TRUE(scratch.tmp_is_empty());
}

// Xvfb stand-ins: one that fails at once, one that never says it is ready.
FailedPlay play_with_xvfb(const Scratch& scratch, const std::string& script, double deadline) {
  return failed_play(stand_in(scratch, "xvfb", script, deadline));
}

TEST(DolphinPlayer, AnXServerThatFailsIsOneLineQuotingIt) {
  Scratch scratch;
  const auto got = play_with_xvfb(scratch, "echo 'Fatal server error: no screens'\nexit 1\n", 20);
  EXPECT_NE(got.what.find("dolphin: Xvfb exited with status 1 before it was ready; its output "
                          "ends: Fatal server error: no screens"),
            std::string::npos)
      << got.what;
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, AnXServerThatNeverGetsReadyMeetsTheDeadline) {
  Scratch scratch;
  const auto got = play_with_xvfb(scratch, "sleep 600\n", 1);
  EXPECT_NE(got.what.find("dolphin: Xvfb was not ready before the deadline"), std::string::npos)
      << got.what;
  EXPECT_GE(got.took, std::chrono::seconds(1));
  EXPECT_LT(got.took, std::chrono::seconds(5));  // the deadline, then at most 2 s of SIGTERM
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, AFileThatIsNotAFifoLogIsDolphinsOwnLineWithNothingLeft) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  const auto log = scratch / "not_a_log.dff";
  test::write_file(log, std::string(2000, 'x'));
  DolphinOptions options;
  options.deadline_seconds = 30;
  const auto start = Clock::now();
  const std::string what = input_error_of([&] { play_fifo_log(log, options); });
  EXPECT_LT(Clock::now() - start, std::chrono::seconds(30));
  // Dolphin checks the file's magic number and says so [DHW FifoDataFile.cpp Load].
  EXPECT_NE(what.find("dolphin: exited with status 1 before dumping a frame"), std::string::npos)
      << what;
  EXPECT_NE(what.find("magic number"), std::string::npos) << what;
  EXPECT_EQ(what.find('\n'), std::string::npos) << what;
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, ADirectoryIsRefusedBeforeAnythingStarts) {
  Scratch scratch;
  const std::string what = input_error_of([&] { play_fifo_log(scratch.tmp(), DolphinOptions{}); });
  EXPECT_NE(what.find("not a regular file"), std::string::npos) << what;
  EXPECT_TRUE(scratch.tmp_is_empty());
}

// The deadlines and graces below are short: the stand-ins never dump a frame, so any deadline
// meets them, and each second here is a second of the suite's wall time spent waiting.
TEST(DolphinPlayer, DeadlineKillsAProgramThatIgnoresSigintAndItsChildren) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  DolphinOptions options =
      stand_in(scratch, "dolphin", "trap '' INT\nsleep 600 &\nwait\nwait\n", 0.5);
  options.stop_grace_seconds = 0.5;
  const auto got = failed_play(options);
  EXPECT_NE(got.what.find("dolphin: no frame dumped within 0.5 s"), std::string::npos) << got.what;
  // The deadline, then SIGINT's grace, which the script ignores, then SIGKILL.
  EXPECT_GE(got.took, std::chrono::milliseconds(1000));
  EXPECT_LT(got.took, std::chrono::seconds(4));
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, DeadlineStopsWhatAProgramLeftAfterItsCleanExit) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  // SIGINT ends the script at once; its background `sleep` (which ignores SIGINT, as background
  // jobs of a script do) stays unless the whole group is killed.
  DolphinOptions options =
      stand_in(scratch, "dolphin", "trap 'exit 0' INT\nsleep 600 &\nwait\n", 0.5);
  options.stop_grace_seconds = 2;
  const auto got = failed_play(options);
  EXPECT_NE(got.what.find("no frame dumped within 0.5 s"), std::string::npos) << got.what;
  // Not the deadline and the whole grace: the script's exit ends the play's wait at once.
  EXPECT_LT(got.took, std::chrono::milliseconds(2500));
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, ACrashIsOneLineNamingTheSignalAndQuotingTheOutput) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  const auto got = play_stand_in(scratch, "echo 'last words'\nsleep 600 &\nkill -SEGV $$\n", 20);
  EXPECT_NE(got.what.find("dolphin: was killed by signal 11 (Segmentation fault) before dumping "
                          "a frame; its output ends: last words"),
            std::string::npos)
      << got.what;
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, AnExitWithoutAFrameSaysSo) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  const auto got = play_stand_in(scratch, "echo 'nothing to show'\n", 20);
  EXPECT_NE(got.what.find("dolphin: exited without dumping a frame"), std::string::npos)
      << got.what;
  EXPECT_NE(got.what.find("its output ends: nothing to show"), std::string::npos) << got.what;
  expect_nothing_left(scratch);
}

// A stand-in that dumps `count` frames the way Dolphin names them (framedump_1.png ...), frame
// i a flat grey of i * 20, and records how it was started.
std::string dumping_script(const std::filesystem::path& frames, int count,
                           const std::filesystem::path& record) {
  return "while [ $# -gt 0 ]; do [ \"$1\" = -u ] && user=\"$2\"; echo \"$1\" >> '" +
         record.string() + "'; shift; done\n" + "echo \"DISPLAY=$DISPLAY\" >> '" + record.string() +
         "'\n" + "cp \"$user/Config/Dolphin.ini\" '" + record.string() + ".ini'\n" +
         "mkdir -p \"$user/Dump/Frames\"\n" + "i=1; while [ $i -le " + std::to_string(count) +
         " ]; do cp '" + frames.string() +
         "'/$i.png \"$user/Dump/Frames/framedump_$i.png\"; i=$((i + 1)); done\n";
}

TEST(DolphinPlayer, FramesComeBackInTheOrderDolphinNumberedThem) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  const auto frames = scratch / "frames";
  std::filesystem::create_directories(frames);
  constexpr int kFrames = 11;  // framedump_10 and _11 must come after framedump_9
  for (int i = 1; i <= kFrames; ++i) {
    Image flat(4, 2);
    for (std::size_t p = 0; p < flat.pixel_count(); ++p) {
      for (int c = 0; c < 3; ++c) flat.rgba[p * 4 + c] = static_cast<float>(i * 20) / 255.0f;
    }
    write_image(frames / (std::to_string(i) + ".png"), flat);
  }
  DolphinOptions options;
  options.executable = (scratch / "dumps").string();
  const auto record = scratch / "started_with";
  write_script(options.executable, dumping_script(frames, kFrames, record));
  options.deadline_seconds = 20;
  const std::vector<Image> got = play_fifo_log(some_bytes(), options);
  ASSERT_EQ(got.size(), static_cast<std::size_t>(kFrames));
  for (int i = 1; i <= kFrames; ++i) {
    const Image& frame = got[static_cast<std::size_t>(i - 1)];
    ASSERT_EQ(frame.width, 4);
    ASSERT_EQ(frame.height, 2);
    EXPECT_NEAR(frame.at(3, 1)[0], static_cast<float>(i * 20) / 255.0f, 1e-6) << "frame " << i;
    EXPECT_EQ(frame.at(3, 1)[3], 1.0f) << "an RGB dump is fully covered";
  }
  // Started as the software renderer on X11 (headless fails for it) on the private display.
  const std::string started = test::read_file(record);
  EXPECT_NE(started.find("-p\nx11\n-v\nSoftware Renderer\n-e\n"), std::string::npos) << started;
  EXPECT_TRUE(std::regex_search(started, std::regex("DISPLAY=:[0-9]+\n"))) << started;
  // ... playing the log once, so that it exits by itself.
  EXPECT_NE(test::read_file(record.string() + ".ini").find("LoopReplay = False"),
            std::string::npos);
  expect_nothing_left(scratch);
}

TEST(DolphinPlayer, TheKeepVariableKeepsTheSessionDirectory) {
  SKIP_WITHOUT_DOLPHIN();
  Scratch scratch;
  const auto frames = scratch / "frames";
  std::filesystem::create_directories(frames);
  write_image(frames / "1.png", Image(4, 2));
  DolphinOptions options;
  options.executable = (scratch / "dumps").string();
  write_script(options.executable, dumping_script(frames, 1, scratch / "started_with"));
  ::setenv(judge::kKeepDolphinDirVariable, "1", 1);
  const auto got = play_fifo_log(some_bytes(), options);
  ::unsetenv(judge::kKeepDolphinDirVariable);
  EXPECT_EQ(got.size(), 1u);
  std::vector<std::filesystem::path> kept;
  for (const auto& e : std::filesystem::directory_iterator(scratch.tmp())) kept.push_back(e);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(std::filesystem::exists(kept[0] / "frame.dff"));
  EXPECT_TRUE(std::filesystem::exists(kept[0] / "user" / "Dump" / "Frames" / "framedump_1.png"));
  EXPECT_TRUE(std::filesystem::exists(kept[0] / "user" / "Config" / "GFX.ini"));
}

TEST(DolphinPlayer, TheQuotedTailIsTheLastNonEmptyLinesWithoutControlCharacters) {
  TempDir dir;
  std::string text = "first\nsecond\n\n  third \r\nfourth\n";
  text += std::string(1, '\0') + "\n";  // how Dolphin ends its output
  test::write_file(dir / "out", text);
  EXPECT_EQ(judge::log_tail(dir / "out"), "second | third | fourth");
  EXPECT_EQ(judge::log_tail(dir / "out", 3, 10), "...d | fourth");
  EXPECT_EQ(judge::log_tail(dir / "missing"), "");
}

// Measured with Debian's dolphin-emu 5.0-17995 (docs/dolphin-judge.md): XFB -> dump size.
TEST(DolphinPlayer, OnlyA4To3SizeWithWholeVideoWordsIsDumpedUnscaled) {
  EXPECT_TRUE(judge::dumped_unscaled(320, 240));   // -> 320x240
  EXPECT_TRUE(judge::dumped_unscaled(640, 480));   // -> 640x480
  EXPECT_TRUE(judge::dumped_unscaled(160, 120));   // -> 160x120
  EXPECT_FALSE(judge::dumped_unscaled(400, 240));  // -> 400x300
  EXPECT_FALSE(judge::dumped_unscaled(304, 200));  // -> 304x228
  EXPECT_FALSE(judge::dumped_unscaled(640, 528));  // -> 704x528
  EXPECT_FALSE(judge::dumped_unscaled(320, 236));  // -> 320x240
  EXPECT_FALSE(judge::dumped_unscaled(640, 256));  // -> 640x480
  EXPECT_FALSE(judge::dumped_unscaled(100, 75));   // 4:3, but the VI shows 96 of 100 pixels
}

// `render --via dolphin`: every refusal is exit 2, one line, and no output file.
struct CliRefusal {
  std::string name, options, says;
};

class RenderViaDolphin : public ::testing::TestWithParam<CliRefusal> {};

TEST_P(RenderViaDolphin, RefusesWithOneLineAndWritesNothing) {
  TempDir dir;
  const std::string scene = (test::source_dir() / "scenes" / "backlit_sphere.json").string();
  std::string options = GetParam().options;
  if (options.find("-o ") == std::string::npos) options += " -o 'DIR/out.png'";
  options = std::regex_replace(options, std::regex("DIR"), dir.path().string());
  const auto r = test::run_ltrender("render '" + scene + "' " + options, test::RunLimits{60, 0});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(GetParam().says), std::string::npos) << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

INSTANTIATE_TEST_SUITE_P(
    Cli, RenderViaDolphin,
    ::testing::Values(
        CliRefusal{"PathWithoutFifoLog", "--path glsl --via dolphin",
                   "--via dolphin: path glsl models no console"},
        CliRefusal{"GroundTruthPath", "--path reference --via dolphin",
                   "path reference models no console"},
        CliRefusal{"ViaOtherThanDolphin", "--path gx --via vulkan", "--via"},
        CliRefusal{"ExrOutput", "--path glsl --via dolphin -o 'DIR/out.exr'", "use a .png"},
        CliRefusal{"KeptLogNotDff", "--path glsl --via dolphin --keep-fifo-log 'DIR/frame.txt'",
                   "use a .dff"},
        CliRefusal{"KeepWithoutVia", "--path gx --keep-fifo-log 'DIR/frame.dff'", "--via"},
        CliRefusal{"DeadlineNan", "--path gx --via dolphin --dolphin-deadline nan",
                   "--dolphin-deadline"},
        CliRefusal{"DeadlineInf", "--path gx --via dolphin --dolphin-deadline inf",
                   "--dolphin-deadline"},
        CliRefusal{"DeadlineZero", "--path gx --via dolphin --dolphin-deadline 0",
                   "--dolphin-deadline"},
        CliRefusal{"DeadlineNegative", "--path gx --via dolphin --dolphin-deadline -5",
                   "--dolphin-deadline"},
        CliRefusal{"DeadlineWithoutVia", "--path gx --dolphin-deadline 5", "--via"}),
    [](const auto& param) { return param.param.name; });

}  // namespace
}  // namespace lt
