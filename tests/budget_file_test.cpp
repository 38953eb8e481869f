// `ltrender budget FILE...` on hand-written ARB programs: exit 0 / 1 (naming the limit) / 2
// (file:line:column), the JSON schema of docs/budget.md, recognition by extension or header, the
// partner profile for the other program kind, and several files in one run.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "test_util.h"

namespace lt {
namespace {

const char kFits[] =
    "!!ARBfp1.0\nOPTION ARB_precision_hint_fastest;\nTEMP a;\n"
    "TEX a, fragment.texcoord[0], texture[0], 2D;\nMUL result.color, a, {0.5, 0.5, 0.5, 1};\n"
    "END\n";

// 65 ALU instructions: one more than ps_2_0's 64.
std::string over_ps20() {
  std::string s = "!!ARBfp1.0\nTEMP a;\nMOV a, fragment.color;\n";
  for (int i = 0; i < 63; ++i) s += "ADD a, a, {0.5, 0.25, 1, 2};\n";
  return s + "MOV result.color, a;\nEND\n";
}

TEST(BudgetFile, FittingProgramExitsZeroWithMesasFigures) {
  const test::TempDir dir;
  test::write_file(dir / "p.fp", kFits);
  const test::RunResult r = test::run_ltrender("budget " + (dir / "p.fp").string());
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("fits ps_2_0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("NATIVE"), std::string::npos) << r.out;
}

TEST(BudgetFile, JsonFollowsTheDocumentedSchema) {
  const test::TempDir dir;
  test::write_file(dir / "p.fp", kFits);
  const test::RunResult r = test::run_ltrender("budget " + (dir / "p.fp").string() + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema"], "ltrender-budget-arb-1");
  EXPECT_EQ(j["kind"], "fragment");
  EXPECT_EQ(j["profile"], "ps_2_0");
  EXPECT_TRUE(j["fits"].get<bool>());
  EXPECT_EQ(j["options"][0], "ARB_precision_hint_fastest");
  for (const char* key : {"alu", "tex", "instruction_slots", "temporaries", "parameters",
                          "attributes", "indirections", "address_registers"}) {
    EXPECT_TRUE(j["counts"].contains(key)) << key;
    EXPECT_TRUE(j["limits"].contains(key)) << key;
    EXPECT_TRUE(j["mesa"]["native"].contains(key)) << key;
    EXPECT_TRUE(j["mesa"]["agrees"][key].get<bool>()) << key;
    EXPECT_TRUE(j["rules"].contains(key)) << key;
  }
  // By hand: MUL is ALU, TEX is TEX, one declared temporary, one inline constant, one input.
  EXPECT_EQ(j["counts"]["alu"], 1);
  EXPECT_EQ(j["counts"]["tex"], 1);
  EXPECT_EQ(j["counts"]["temporaries"], 1);
  EXPECT_EQ(j["counts"]["parameters"], 1);
  EXPECT_EQ(j["counts"]["attributes"], 1);
  EXPECT_EQ(j["limits"]["alu"], 64);
  EXPECT_TRUE(j["limits"]["address_registers"].is_null());
  EXPECT_EQ(j["mesa"]["native"]["instruction_slots"], 3) << "Mesa counts END";
  EXPECT_TRUE(j["over"].empty());
}

TEST(BudgetFile, OverBudgetExitsOneNamingTheLimit) {
  const test::TempDir dir;
  test::write_file(dir / "big.fp", over_ps20());
  const test::RunResult r = test::run_ltrender("budget " + (dir / "big.fp").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_NE(r.err.find("65 ALU instructions > 64 (ps_2_0)"), std::string::npos) << r.err;
  // ps_2_x counts 96 slots for ALU and TEX together: 65 fit.
  const test::RunResult x =
      test::run_ltrender("budget " + (dir / "big.fp").string() + " --profile ps_2_x");
  EXPECT_EQ(x.exit_code, 0) << x.err;
}

TEST(BudgetFile, InvalidProgramExitsTwoWithLineAndColumn) {
  const test::TempDir dir;
  const std::string file = (dir / "bad.fp").string();
  test::write_file(file, "!!ARBfp1.0\nTEMP a;\nMOV a, fragment.color\nMOV result.color, a;\nEND\n");
  const test::RunResult r = test::run_ltrender("budget " + file);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ltrender: error: " + file + ":4:1: expected ';', found 'MOV'\n");
}

// A file of no known extension is an ARB program by its header (after white space).
TEST(BudgetFile, TheHeaderNamesTheKindWhateverTheExtension) {
  const test::TempDir dir;
  test::write_file(dir / "vertex.txt",
                   "\n  !!ARBvp1.0\nOPTION ARB_position_invariant;\nMOV result.color, "
                   "vertex.color;\nEND\n");
  const test::RunResult r =
      test::run_ltrender("budget " + (dir / "vertex.txt").string() + " --profile ps_2_0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "vertex");
  EXPECT_EQ(j["profile"], "vs_2_0") << "ps_2_0's partner checks a vertex program";
  // 1 instruction + the 4 DP4 of position invariance; Mesa's native count is 1 + END.
  EXPECT_EQ(j["counts"]["instruction_slots"], 5);
  EXPECT_EQ(j["mesa"]["native"]["instruction_slots"], 2);
  EXPECT_EQ(j["mesa"]["api_instructions"], 6) << "Mesa appends the 4 DP4";
}

TEST(BudgetFile, SeveralFilesReportEachAndExitWithTheWorst) {
  const test::TempDir dir;
  test::write_file(dir / "a.fp", kFits);
  test::write_file(dir / "big.arb", over_ps20());
  test::write_file(dir / "bad.vp", "!!ARBvp1.0\nMOV result.position, vertex.nowhere;\nEND\n");
  const std::string a = (dir / "a.fp").string(), big = (dir / "big.arb").string(),
                    bad = (dir / "bad.vp").string();
  const test::RunResult over = test::run_ltrender("budget " + a + " " + big);
  EXPECT_EQ(over.exit_code, 1) << over.err;
  EXPECT_NE(over.out.find("fits ps_2_0"), std::string::npos);
  EXPECT_NE(over.out.find("OVER BUDGET"), std::string::npos);
  const test::RunResult r = test::run_ltrender("budget " + a + " " + bad + " " + big);
  EXPECT_EQ(r.exit_code, 2) << "an invalid file outranks an overrun";
  EXPECT_NE(r.out.find("OVER BUDGET"), std::string::npos) << "the valid files are still counted";
  EXPECT_EQ(r.err.rfind("ltrender: error: " + bad + ":2:29: expected a vertex attribute", 0), 0u)
      << r.err;
}

}  // namespace
}  // namespace lt
