// advise names a texture format (issue 47): on the grey thickness map scene, the pick is tried
// with each format of kGreyMapFormats (with the I8 LUT) and the LUT in I4, each rendered; under a
// loose budget the format advised is the one of fewest MEM1 bytes (texels and palette), then
// fewest TMEM bytes, each as `ltrender budget --path gx --json` counts them (run apart, here);
// under a mean budget between two formats' errors, a format over it is never the pick; the
// picked format's error is advise's as render_scene and compare_images measure it apart. Small
// renders (48 pixels wide): the search, not the image, is under test.
#include <gtest/gtest.h>

#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>

#include "advise/texture_advice.h"
#include "advise_error_check.h"
#include "core/build_paths.h"
#include "test_util.h"

namespace lt::advise {
namespace {

const fs::path kMapScene = lt::build_paths::source_dir() / "scenes" / "maps" / "sphere_map.json";

nlohmann::json advise_textures_json(const fs::path& dir, const std::string& budget_args,
                                    int expected_exit) {
  const fs::path json = dir / "advise.json";
  const test::RunResult r =
      test::run_ltrender("advise " + kMapScene.string() + " --target wii-tev --width 48 " +
                         budget_args + " --json " + json.string());
  EXPECT_EQ(r.exit_code, expected_exit) << r.out << r.err;
  EXPECT_NE(r.out.find("textures (grey thickness map): "), std::string::npos) << r.out;
  return nlohmann::json::parse(test::read_file(json));
}

TEST(AdviseTexture, ALooseBudgetPicksTheFormatOfFewestBytesAndAMeanBudgetLeavesTheWorseOut) {
  test::TempDir dir;
  const nlohmann::json loose = advise_textures_json(dir.path(), "--max-lsb 255", 0);
  ASSERT_EQ(loose["materials"].size(), 1u);
  const nlohmann::json& m = loose["materials"][0];
  ASSERT_TRUE(m["pick"].is_string()) << m;
  ASSERT_TRUE(m.contains("textures")) << m;
  EXPECT_EQ(m["textures"]["maps"], "grey thickness map");
  const nlohmann::json& options = m["textures"]["options"];
  ASSERT_EQ(options.size(), std::size(kGreyMapFormats) + 1);  // + the I4 LUT
  // Each option's bytes from the budget's command; the expected pick is the least by (MEM1,
  // TMEM, mean error): every option is within 255 LSB, 8-bit output's whole range.
  using Rank = std::tuple<std::size_t, std::size_t, double>;
  Rank best{std::numeric_limits<std::size_t>::max(), 0, 0};
  std::string expected_map, expected_lut;
  double lowest_mean = 1e9, highest_mean = 0;
  for (std::size_t i = 0; i < options.size(); ++i) {
    const nlohmann::json& o = options[i];
    ASSERT_EQ(o["failed"], "") << o;
    const std::string map = i < std::size(kGreyMapFormats) ? kGreyMapFormats[i] : "i8";
    const std::string lut = i < std::size(kGreyMapFormats) ? "i8" : "i4";
    EXPECT_EQ(o["map_format"], map);
    EXPECT_EQ(o["lut_format"], lut);
    const std::string variant = o["variant"];
    EXPECT_NE(variant.find(map == "i8" ? "" : ":map=" + map), std::string::npos) << variant;
    EXPECT_EQ(variant.find(":lut-format=") != std::string::npos, lut != "i8") << variant;
    const test::RunResult b = test::run_ltrender("budget " + kMapScene.string() +
                                                 " --path gx --variant " + variant + " --json");
    ASSERT_EQ(b.exit_code, 0) << b.err;
    const nlohmann::json details = nlohmann::json::parse(b.out).at("details");
    const std::size_t tlut =
        details.contains("tlut_bytes") ? details["tlut_bytes"].get<size_t>() : 0;
    EXPECT_EQ(o["texture_bytes"], details.at("texture_bytes")) << variant;
    EXPECT_EQ(o["tlut_bytes"], tlut) << variant;
    EXPECT_EQ(o["tmem_bytes"], details.at("tmem_bytes")) << variant;
    EXPECT_EQ(o["non_finite_pixels"], 0) << variant;
    const double mean = o["error"]["mean"];
    lowest_mean = std::min(lowest_mean, mean);
    highest_mean = std::max(highest_mean, mean);
    const Rank r{details.at("texture_bytes").get<std::size_t>() + tlut,
                 details.at("tmem_bytes").get<std::size_t>(), o["error"]["max"].get<double>()};
    if (r < best) {
      best = r;
      expected_map = map;
      expected_lut = lut;
    }
  }
  EXPECT_EQ(m["textures"]["pick"]["map_format"], expected_map);
  EXPECT_EQ(m["textures"]["pick"]["lut_format"], expected_lut);
  EXPECT_EQ(m["textures"]["pick"]["mem1_bytes"], std::get<0>(best));
  EXPECT_NE(expected_map, "i8") << "a 4-bit map holds the material within 255 LSB in fewer bytes";
  // The picked format's error, measured again outside advise (advise_error_check.h).
  std::size_t measured = 0;
  for (const nlohmann::json& o : options) {
    if (o["variant"] != m["textures"]["pick"]["variant"]) continue;
    test::expect_advise_error_is_measured_again(kMapScene, loose, o["variant"], o["error"]);
    ++measured;
  }
  EXPECT_EQ(measured, 1u);

  // A mean budget between the formats' lowest and highest mean errors: the picked format is
  // within it.
  ASSERT_LT(lowest_mean, highest_mean) << "the formats' errors differ";
  const double budget = (lowest_mean + highest_mean) / 2;
  const nlohmann::json mean =
      advise_textures_json(dir.path(), "--stat mean --max-lsb " + std::to_string(budget), 0);
  const nlohmann::json& t = mean["materials"][0]["textures"];
  ASSERT_TRUE(t["pick"].is_object()) << t;
  for (const nlohmann::json& o : t["options"]) {
    if (o["variant"] == t["pick"]["variant"]) EXPECT_LE(o["error"]["mean"].get<double>(), budget);
  }
}

}  // namespace
}  // namespace lt::advise
