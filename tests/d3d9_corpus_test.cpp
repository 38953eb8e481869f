// Direct3D 9 programs from public repositories, each fxc's own output with fxc's count in a
// comment ("; N ALU, M TEX", kept by Unity 3/4 in the d3d9 subprograms of compiled shaders, or
// an fxc listing's "// approximately N instruction slots used"): tests/data/d3d9, every file's
// repository, path and commit in SOURCES.tsv. The
// expectation is fxc's figure, read here from the comment; the counter never sees it.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <regex>
#include <sstream>

#include "core/fs.h"
#include "d3d9/d3d9_asm_counter.h"
#include "d3d9/d3d9_asm_parser.h"
#include "test_util.h"

namespace lt {
namespace {

const fs::path& corpus_dir() {
  static const fs::path dir = test::source_dir() / "tests" / "data" / "d3d9";
  return dir;
}

std::vector<fs::path> corpus_programs() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(corpus_dir())) {
    const std::string ext = e.path().extension().string();
    if (ext == ".vsh" || ext == ".psh") out.push_back(e.path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST(D3d9Corpus, EveryProgramNamesWhereItCameFrom) {
  std::map<std::string, std::string> rows;  // file -> the rest of its row
  std::istringstream in(test::read_file(corpus_dir() / "SOURCES.tsv"));
  const std::regex row(R"(([^\t]+)\t([\w.-]+/[\w.-]+)\t([^\t]+)\t([0-9a-f]{40})\t(\d+))");
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::smatch m;
    ASSERT_TRUE(std::regex_match(line, m, row)) << "file, owner/name, path, commit, line: " << line;
    rows[m[1]] = line;
  }
  const std::vector<fs::path> programs = corpus_programs();
  EXPECT_GE(programs.size(), 40u);
  for (const fs::path& p : programs) {
    EXPECT_EQ(rows.count(p.filename().string()), 1u) << p << " has no row in SOURCES.tsv";
  }
  EXPECT_EQ(rows.size(), programs.size()) << "a row names a file that is not there";
}

// Our ALU and TEX slots against fxc's on every program, tallied per version (the table of
// docs/budget.md): all must agree.
TEST(D3d9Corpus, SlotsEqualFxcsCommentOnEveryProgram) {
  // Unity's header comment, or the last line of an fxc listing (a vertex shader's without the
  // parenthesis: every slot arithmetic).
  const std::regex unity(R"(\n; (\d+) ALU(, (\d+) TEX)?\n)");
  const std::regex listing(
      R"(// approximately (\d+) instruction slots used( \((\d+) texture, (\d+) arithmetic\))?)");
  std::map<std::string, std::pair<int, int>> agree;  // version -> (agreeing, programs)
  for (const fs::path& p : corpus_programs()) {
    const std::string text = test::read_file(p);
    std::smatch m;
    int alu = 0, tex = 0;
    if (std::regex_search(text, m, unity)) {
      alu = std::stoi(m[1]);
      tex = m[3].matched ? std::stoi(m[3]) : 0;
    } else {
      ASSERT_TRUE(std::regex_search(text, m, listing)) << p << " has no fxc count";
      tex = m[2].matched ? std::stoi(m[3]) : 0;
      alu = m[2].matched ? std::stoi(m[4]) : std::stoi(m[1]);
    }
    const d3d9::Program program = d3d9::parse(text);
    const d3d9::Counts c = d3d9::count(program);
    const bool same = c.arithmetic == alu && c.texture == tex;
    EXPECT_TRUE(same) << p.filename() << ": ours " << c.arithmetic << " ALU, " << c.texture
                      << " TEX; fxc " << alu << " ALU, " << tex << " TEX";
    // fxc compiled these for ps_2_0, which refuses a read past third order (4 levels).
    if (program.version == d3d9::Version::Ps20) {
      EXPECT_LE(c.dependent_levels, 4) << p.filename();
    }
    std::pair<int, int>& a = agree[d3d9::to_string(program.version)];
    a.first += same;
    a.second += 1;
  }
  for (const auto& [version, a] : agree) {
    std::cout << "D3D9 corpus: " << version << " " << a.first << "/" << a.second
              << " equal fxc's count\n";
  }
  EXPECT_EQ(agree.size(), 5u) << "vs_1_1, vs_2_0, vs_3_0, ps_2_0 and ps_3_0 programs";
}

}  // namespace
}  // namespace lt
