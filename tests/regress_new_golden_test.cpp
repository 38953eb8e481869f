// `regress --update` holds a new golden to its path's bound against the reference before it
// writes it (paths/path_bounds.h, docs/regress.md "A new golden"): within the bound it says so;
// outside it the golden is written but the case warns, naming the bound; a variant whose bound
// is per demo scene only says the golden is unchecked. The expectation outside: a 16-texel LUT
// cannot hold t^128 (power_128), an error of tens of LSB where the row allows 12.
#include <gtest/gtest.h>

#include <string>

#include "test_util.h"

namespace lt {
namespace {

// The output line of the case `id` ("scene/path/variant").
std::string line_of(const std::string& out, const std::string& id) {
  const size_t at = out.find(" " + id + ": ");
  if (at == std::string::npos) return "";
  const size_t start = out.rfind('\n', at) + 1;
  return out.substr(start, out.find('\n', at) - start);
}

TEST(RegressNewGolden, IsHeldToItsPathsBoundBeforeItIsWritten) {
  test::TempDir dir;
  const std::string scenes = (test::source_dir() / "scenes/hard/power_128.json").string() + " " +
                             (test::source_dir() / "scenes/backlit_sphere.json").string();
  const auto goldens = dir.path() / "goldens";
  const auto run = test::run_ltrender("regress " + scenes +
                                      " --paths arbfp:pow=lut:16:u8,gx --width 64 --height 48 "
                                      "--update --goldens " +
                                      goldens.string());
  EXPECT_EQ(run.exit_code, 0) << run.out << run.err;

  const std::string outside = line_of(run.out, "power_128/arbfp/pow=lut:16:u8");
  EXPECT_EQ(outside.rfind("warn ", 0), 0u) << outside;
  EXPECT_NE(outside.find("warn: outside arbfp:pow=lut:16:u8's bound to the reference (covered "
                         "max "),
            std::string::npos)
      << outside;
  EXPECT_NE(outside.find("over the bound's 12.00"), std::string::npos) << outside;
  EXPECT_TRUE(fs::exists(goldens / "power_128__arbfp__pow_lut_16_u8.png"))
      << "a warned golden is still written";

  const std::string within = line_of(run.out, "backlit_sphere/arbfp/pow=lut:16:u8");
  EXPECT_EQ(within.rfind("created ", 0), 0u) << within;
  EXPECT_NE(within.find("within arbfp:pow=lut:16:u8's bound to the reference"), std::string::npos)
      << within;

  const std::string unchecked = line_of(run.out, "backlit_sphere/gx/t=vertex");
  EXPECT_NE(unchecked.find("unchecked: gx:t=vertex has a bound on the demo scenes only"),
            std::string::npos)
      << unchecked;

  // An existing golden is not held again: the second --update keeps it.
  const auto again = test::run_ltrender("regress " + scenes +
                                        " --paths arbfp:pow=lut:16:u8 --width 64 --height 48 "
                                        "--update --goldens " +
                                        goldens.string());
  EXPECT_EQ(line_of(again.out, "power_128/arbfp/pow=lut:16:u8").rfind("kept ", 0), 0u) << again.out;
}

}  // namespace
}  // namespace lt
