// Several approved goldens a case, keyed by renderer, with two real renderers: Mesa's llvmpipe
// (the default) and softpipe (GALLIUM_DRIVER=softpipe), both in Debian's libOSMesa. A folder
// updated on one and then on the other passes on both, each held to its own image, the shared
// golden unchanged where it passed; a failure names every image it was held to; a bad key and
// an override folder that is a file are refused.
#include <gtest/gtest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>

#include "regress/golden_key.h"
#include "regress_fixture.h"
#include "test_util.h"

namespace lt {
namespace {

// The Gallium driver for what a test runs, and the default after it.
class DriverScope {
 public:
  explicit DriverScope(const char* driver) { ::setenv("GALLIUM_DRIVER", driver, 1); }
  ~DriverScope() { ::unsetenv("GALLIUM_DRIVER"); }
};

TEST(GoldenKey, IsTheRenderersFirstWordAndTheMesaRelease) {
  EXPECT_EQ(golden_key_from("llvmpipe (LLVM 15.0.6, 256 bits)",
                            "4.5 (Compatibility Profile) Mesa 22.3.6"),
            "llvmpipe-mesa-22.3.6");
  EXPECT_EQ(golden_key_from("softpipe", "3.3 (Compatibility Profile) Mesa 22.3.6"),
            "softpipe-mesa-22.3.6");
  EXPECT_EQ(golden_key_from("Some GPU/X", "4.6 NVIDIA 535"), "some");
}

class RegressGoldens : public ::testing::Test {
 protected:
  void SetUp() override {
    // Any difference fails: where the two rasterisers differ by an LSB, one golden cannot hold
    // both.
    test::write_quad_scene(dir.path(), "quad_a", 4,
                           R"("regress": {"fail_lsb": 0, "hard_fail_lsb": 0})");
    test::write_quad_scene(dir.path(), "quad_b", 16,
                           R"("regress": {"fail_lsb": 0, "hard_fail_lsb": 0})");
  }
  test::RunResult run(const std::string& extra = "") const {
    return test::run_ltrender("regress " + (dir / "quad_a.json").string() + " " +
                              (dir / "quad_b.json").string() + " --goldens " +
                              (dir / "goldens").string() +
                              " --paths reference,glsl,arbfp,combiners --json " +
                              (dir / "run.json").string() + " " + extra);
  }
  nlohmann::json cases() const {
    return nlohmann::json::parse(test::read_file(dir / "run.json"))["cases"];
  }
  test::TempDir dir;
};

TEST_F(RegressGoldens, UpdatedOnLlvmpipeThenSoftpipePassesOnBoth) {
  ASSERT_EQ(run("--update").exit_code, 0);
  std::map<std::string, std::string> shared;
  for (const auto& e : fs::directory_iterator(dir / "goldens"))
    if (e.is_regular_file()) shared[e.path().filename()] = test::read_file(e.path());
  ASSERT_EQ(shared.size(), 8u);

  std::string softpipe_key;
  {
    const DriverScope softpipe("softpipe");
    const auto before = run();
    // Some case must differ between the two renderers, or this test proves nothing.
    ASSERT_EQ(before.exit_code, 1) << before.out;
    const auto update = run("--update");
    EXPECT_EQ(update.exit_code, 0) << update.err;
    for (const auto& c : cases()) {
      if (c["status"] == "created") {
        softpipe_key = fs::path(c["golden"].get<std::string>()).parent_path().filename();
      }
    }
    ASSERT_EQ(softpipe_key.rfind("softpipe-mesa-", 0), 0u) << update.out;
    const auto after = run();
    EXPECT_EQ(after.exit_code, 0) << after.out;
    size_t own = 0;
    for (const auto& c : cases())
      own += c["golden"].get<std::string>().find(softpipe_key) != std::string::npos;
    EXPECT_GT(own, 0u);
  }
  // llvmpipe still passes on the shared goldens, which the softpipe update left as they were.
  const auto llvmpipe = run();
  EXPECT_EQ(llvmpipe.exit_code, 0) << llvmpipe.out;
  for (const auto& c : cases())
    EXPECT_EQ(c["golden"].get<std::string>().find(softpipe_key), std::string::npos) << c["id"];
  for (const auto& [name, bytes] : shared)
    EXPECT_EQ(test::read_file(dir / "goldens" / name), bytes) << name;

  // A failure names every image it was held to.
  for (const auto& e : fs::directory_iterator(dir / "goldens" / softpipe_key)) {
    test::push_pixel(e.path(), 3, 3, 5);
    test::push_pixel(dir / "goldens" / e.path().filename(), 3, 3, 5);
    const DriverScope softpipe("softpipe");
    const auto failed = run();
    EXPECT_EQ(failed.exit_code, 1);
    EXPECT_NE(failed.out.find("; held to " + e.path().string() + " (fail, max "), std::string::npos)
        << failed.out;
    EXPECT_NE(
        failed.out.find(", " + (dir / "goldens" / e.path().filename()).string() + " (fail, max "),
        std::string::npos)
        << failed.out;
    break;
  }
}

TEST_F(RegressGoldens, ABadKeyOrAnOverrideFolderThatIsAFileIsRefused) {
  const auto bad = run("--golden-key 'a/b'");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("ltrender: error: --golden-key:a/b: may hold only"), std::string::npos)
      << bad.err;
  fs::create_directories(dir / "goldens");
  test::write_file(dir / "goldens" / "ci-key", "not a folder");
  const auto file = run("--golden-key ci-key --update");
  EXPECT_EQ(file.exit_code, 2);
  EXPECT_EQ(file.err, "ltrender: error: " + (dir / "goldens" / "ci-key").string() +
                          ": the folder of the golden key's overrides is a file (--golden-key "
                          "ci-key)\n");
  EXPECT_FALSE(fs::exists(dir / "run.json"));
  size_t written = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir / "goldens")) ++written;
  EXPECT_EQ(written, 1u);
}

}  // namespace
}  // namespace lt
