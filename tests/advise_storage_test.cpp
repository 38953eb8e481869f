// advise picks a vertex storage (issue 46): on a demo scene, each material's pick is tried with
// the storages of kStorages, each rendered; under a loose budget the storage advised is the one
// of fewest FIFO bytes a frame as `ltrender budget --path gx` counts them (run apart, here), and
// each storage's bytes in the advice are the budget's; under 0 LSB no variant holds, so no
// storage is advised; the picked storage's error is advise's as render_scene and compare_images
// measure it apart. Small renders (48 pixels wide): the search, not the image, is under test.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "advise/storage_advice.h"
#include "advise_error_check.h"
#include "core/build_paths.h"
#include "test_util.h"

namespace lt::advise {
namespace {

const fs::path kScene = lt::build_paths::source_dir() / "scenes" / "backlit_sphere.json";

nlohmann::json advise_json(const fs::path& dir, const std::string& max_lsb, int expected_exit) {
  const fs::path json = dir / ("advise_" + max_lsb + ".json");
  const test::RunResult r =
      test::run_ltrender("advise " + kScene.string() + " --target wii-tev --width 48 --max-lsb " +
                         max_lsb + " --json " + json.string());
  EXPECT_EQ(r.exit_code, expected_exit) << r.out << r.err;
  return nlohmann::json::parse(test::read_file(json));
}

TEST(AdviseStorage, ALooseBudgetPicksTheStorageOfFewestFifoBytesAndZeroLsbPicksNone) {
  test::TempDir dir;
  const nlohmann::json loose = advise_json(dir.path(), "255", 0);
  ASSERT_EQ(loose["materials"].size(), 1u);
  const nlohmann::json& m = loose["materials"][0];
  ASSERT_TRUE(m["pick"].is_string()) << m;
  ASSERT_TRUE(m.contains("storage")) << m;
  const nlohmann::json& options = m["storage"]["options"];
  ASSERT_EQ(options.size(), std::size(kStorages));
  // The bytes of each storage, from the budget's command; the fewest is the expected pick
  // (every storage's error is within 255 LSB, 8-bit output's whole range).
  std::size_t fewest = std::numeric_limits<std::size_t>::max();
  std::string expected;
  for (std::size_t i = 0; i < options.size(); ++i) {
    const nlohmann::json& o = options[i];
    EXPECT_EQ(o["storage"], kStorages[i]);
    ASSERT_EQ(o["failed"], "") << o;
    const std::string variant = m["pick"].get<std::string>() +
                                (std::string(kStorages[i]).empty() ? "" : ":") + kStorages[i];
    EXPECT_EQ(o["variant"], variant);
    const test::RunResult b = test::run_ltrender("budget " + kScene.string() +
                                                 " --path gx --variant " + variant + " --json");
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const nlohmann::json details = nlohmann::json::parse(b.out).at("details");
    for (const char* key : {"vertex_bytes", "fifo_bytes", "xf_vertices", "texture_bytes"})
      EXPECT_EQ(o[key], details.at(key)) << variant << " " << key;
    // Rendered: a measured error, no non-finite pixel.
    EXPECT_EQ(o["non_finite_pixels"], 0) << variant;
    EXPECT_GE(o["error"]["max"].get<double>(), o["error"]["mean"].get<double>());
    if (details.at("fifo_bytes").get<std::size_t>() < fewest) {
      fewest = details.at("fifo_bytes");
      expected = kStorages[i];
    }
  }
  EXPECT_FALSE(expected.empty()) << "a quantised storage sends fewer bytes than F32";
  EXPECT_EQ(m["storage"]["pick"], expected);
  // The picked storage's error, measured again outside advise (advise_error_check.h).
  std::size_t measured = 0;
  for (const nlohmann::json& o : options) {
    if (o["storage"] != expected) continue;
    test::expect_advise_error_is_measured_again(kScene, loose, o["variant"], o["error"]);
    ++measured;
  }
  EXPECT_EQ(measured, 1u);
  // The F32 option renders the pick itself: its error is the pick's in the search.
  for (const nlohmann::json& c : m["candidates"]) {
    if (c["variant"] == m["pick"]) EXPECT_EQ(options[0]["error"]["max"], c["error"]["max"]);
  }

  // 0 LSB: gx's 8-bit frame cannot be exact here (the search's own errors say so), so no
  // variant is picked and no storage advised; advise exits 1.
  const nlohmann::json exact = advise_json(dir.path(), "0", 1);
  ASSERT_EQ(exact["materials"].size(), 1u);
  EXPECT_TRUE(exact["materials"][0]["pick"].is_null());
  EXPECT_FALSE(exact["materials"][0].contains("storage"));
}

}  // namespace
}  // namespace lt::advise
