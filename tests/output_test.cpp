// Writing outputs (core/fs.h write_atomically): a temporary beside the target, then a rename; a
// failure is cli.md's one line with the real reason, and leaves nothing behind.
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace lt
