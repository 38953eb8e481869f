// The error of replacing a thickness map by vertex colours falls as the mesh gets denser: the
// property behind scripts/map_vs_vertex.py's table (docs/maps.md, "Map or vertex colours?"), run
// through that script on three UV spheres at small sizes so it takes seconds.
//
// Why it must fall: on a faceted sphere the map holds the bake at every texel of a facet while
// vertex colours interpolate it linearly between the corners, an O(h^2) difference in the facet
// size h, so a quarter per doubling of the rings, down to the Monte-Carlo noise of the two bakes
// (64 rays: per-texel noise that the mean averages but never removes). A bound of 0.75 of the
// previous mean per doubling leaves room for that floor (measured 7.20 -> 1.78 -> 0.76 LSB).
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

#include "core/build_paths.h"
#include "test_util.h"

namespace lt {
namespace {

TEST(MapVsVertex, ErrorFallsAsTheTessellationRises) {
  const std::string command = "python3 " +
                              (test::source_dir() / "scripts" / "map_vs_vertex.py").string() +
                              " --bin " + lt::build_paths::ltrender_binary().string() +
                              " --rings 4,8,16 --rays 64 --map 128x64 --width 160 --height 120"
                              " --json";
  const test::CommandOutput run = test::command_output(command);
  ASSERT_EQ(run.exit_code, 0) << command;
  const auto rows = nlohmann::json::parse(run.out);
  ASSERT_EQ(rows.size(), 3u);
  for (size_t i = 1; i < rows.size(); ++i) {
    const auto &coarse = rows[i - 1], &fine = rows[i];
    std::printf("R %d -> %d: mean %.3f -> %.3f, p99 %.2f -> %.2f LSB\n", coarse["rings"].get<int>(),
                fine["rings"].get<int>(), coarse["mean_lsb"].get<double>(),
                fine["mean_lsb"].get<double>(), coarse["p99_lsb"].get<double>(),
                fine["p99_lsb"].get<double>());
    EXPECT_GT(fine["vertices"].get<int>(), coarse["vertices"].get<int>());
    EXPECT_LT(fine["mean_lsb"].get<double>(), 0.75 * coarse["mean_lsb"].get<double>());
    EXPECT_LT(fine["p99_lsb"].get<double>(), coarse["p99_lsb"].get<double>());
  }
  // The coarsest sphere's error is far from nothing: the comparison sees the two thicknesses.
  EXPECT_GT(rows[0]["mean_lsb"].get<double>(), 2.0);
}

}  // namespace
}  // namespace lt
