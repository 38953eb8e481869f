// Usage errors of the binary itself (cli.md): one line on stderr, exit 2, saying what to type.
#include <gtest/gtest.h>

#include <string>

#include "test_util.h"

namespace lt {
namespace {

// Issue 24: an unknown subcommand said "A subcommand is required".
TEST(CliUsage, AnUnknownSubcommandIsNamedWithTheSubcommands) {
  const auto r = test::run_ltrender("frobnicate scene.json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err,
            "ltrender: error: usage: unknown subcommand 'frobnicate' (subcommands: render, "
            "compare, info, bench, bake, budget, meshgen, export, regress, advise, sweep)\n");
  // Every subcommand it lists is one: its --help exits 0.
  for (const char* sub : {"render", "compare", "info", "bench", "bake", "budget", "meshgen",
                          "export", "regress", "advise", "sweep"})
    EXPECT_EQ(test::run_ltrender(std::string(sub) + " --help").exit_code, 0) << sub;
  // No word at all still asks for one.
  const auto none = test::run_ltrender("");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err, "ltrender: error: usage: A subcommand is required\n");
}

}  // namespace
}  // namespace lt
