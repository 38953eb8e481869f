// ARB programs NVIDIA cgc wrote (the opengl subprograms of compiled Unity shaders,
// tests/data/arb, each file's repository, path and commit in SOURCES.tsv), counted by
// `ltrender budget` against two outside figures: Mesa's GL_PROGRAM_NATIVE_* (the report's check)
// and cgc's own comments, "# N ALU, M TEX" and "# N instructions, M R-regs", read here from the
// text. cgc's fragment "N ALU" counts every instruction, texture ones included, and its "M TEX"
// leaves KIL out (ARB_fragment_program and Mesa count KIL as a texture instruction; cgc, as the
// sampling it is not): wavinggrass_1.fp, 2 TEX + 1 KIL, is cgc's "2 TEX" and Mesa's 3.
#include <gtest/gtest.h>

#include <iostream>
#include <iterator>
#include <map>
#include <regex>

#include "budget_test_util.h"
#include "test_util.h"

namespace lt {
namespace {

struct CgcCount {
  int alu = 0, tex = 0, instructions = 0, registers = 0;
};

// KIL instructions in the text, which cgc's TEX leaves out.
int kills(const std::string& text) {
  static const std::regex kil(R"(\nKIL )");
  return static_cast<int>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), kil), std::sregex_iterator()));
}

CgcCount cgc_count(const std::string& text) {
  static const std::regex stats(R"(\n# (\d+) ALU(, (\d+) TEX)?\n)");
  static const std::regex total(R"(\n# (\d+) instructions, (\d+) R-regs)");
  CgcCount c;
  std::smatch m;
  EXPECT_TRUE(std::regex_search(text, m, stats)) << text;
  c.alu = std::stoi(m[1]);
  c.tex = m[3].matched ? std::stoi(m[3]) : 0;
  EXPECT_TRUE(std::regex_search(text, m, total)) << text;
  c.instructions = std::stoi(m[1]);
  c.registers = std::stoi(m[2]);
  return c;
}

TEST(ArbCorpus, CountsEqualCgcsCommentsAndMesas) {
  const fs::path dir = test::source_dir() / "tests" / "data" / "arb";
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.path().extension() == ".fp" || e.path().extension() == ".vp") {
      files.push_back(e.path().string());
    }
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 20u);
  std::string args;
  for (const std::string& f : files) args += " " + f;
  const test::RunResult r = test::run_ltrender("budget" + args + " --json");
  // Exit 1: some are over ps_2_0 (cgc compiled them for arbfp1); none is invalid.
  ASSERT_NE(r.exit_code, 2) << r.err;
  const std::vector<nlohmann::json> all = test::budget_records(r.out);
  ASSERT_EQ(all.size(), files.size());
  std::map<std::string, std::pair<int, int>> with_cgc, with_mesa;  // kind -> (agree, programs)
  for (size_t i = 0; i < files.size(); ++i) {
    const std::string kind = all[i]["details"]["kind"];
    const nlohmann::json& row = all[i]["items"][0];
    const auto used = [&row](const char* key) {
      return test::budget_resource(row, key)["used"].get<int>();
    };
    const std::string text = test::read_file(files[i]);
    const CgcCount cgc = cgc_count(text);
    const int slots = used("instruction_slots");
    const bool fragment = kind == "fragment";
    const int tex = fragment ? used("tex") - kills(text) : 0;
    const bool cgc_same = cgc.alu == slots && cgc.tex == tex && cgc.instructions == slots &&
                          cgc.registers == used("temporaries");
    EXPECT_TRUE(cgc_same) << files[i] << ": ours " << slots << " slots, " << tex << " TEX but KIL, "
                          << used("temporaries") << " temporaries; cgc " << cgc.alu << " ALU, "
                          << cgc.tex << " TEX, " << cgc.instructions << " instructions, "
                          << cgc.registers << " R-regs";
    bool mesa_same = true;
    for (const nlohmann::json& res : row["resources"]) {
      if (!res["check"].is_null()) mesa_same = mesa_same && res["check"]["agrees"].get<bool>();
    }
    EXPECT_TRUE(mesa_same) << files[i] << ": " << row.dump();
    with_cgc[kind].first += cgc_same;
    with_cgc[kind].second += 1;
    with_mesa[kind].first += mesa_same;
    with_mesa[kind].second += 1;
  }
  for (const auto& [kind, a] : with_cgc) {
    std::cout << "ARB corpus: " << kind << " " << a.first << "/" << a.second << " equal cgc's, "
              << with_mesa[kind].first << "/" << with_mesa[kind].second << " equal Mesa's\n";
  }
}

}  // namespace
}  // namespace lt
