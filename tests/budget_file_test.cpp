// `ltrender budget FILE...` on hand-written ARB programs: exit 0 / 1 (naming the limit) / 2
// (file:line:column), the JSON schema of docs/budget.md, recognition by extension or header, the
// partner profile for the other program kind, and several files in one run. Then the one report
// for every kind of input (issue 24): one schema, an error record per invalid file, the file on
// every line, a profile per kind of input, and --path used or refused.
#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "budget_test_util.h"
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

// A resource of the first row of an ltrender-budget-2 record, by key.
nlohmann::json resource(const nlohmann::json& record, const std::string& key) {
  for (const nlohmann::json& r : record["items"][0]["resources"]) {
    if (r["key"] == key) return r;
  }
  ADD_FAILURE() << "no " << key << " in " << record.dump();
  return nlohmann::json::object();
}

TEST(BudgetFile, JsonFollowsTheDocumentedSchema) {
  const test::TempDir dir;
  const std::string file = (dir / "p.fp").string();
  test::write_file(file, kFits);
  const test::RunResult r = test::run_ltrender("budget " + file + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema"], "ltrender-budget-2");
  EXPECT_EQ(j["file"], file);
  EXPECT_EQ(j["input"], "program");
  EXPECT_EQ(j["path"], "arbfp");
  EXPECT_EQ(j["details"]["kind"], "fragment");
  EXPECT_EQ(j["profiles"][0]["name"], "ps_2_0");
  EXPECT_EQ(j["items"][0]["scope"], "program");
  EXPECT_EQ(j["items"][0]["profile"], "ps_2_0");
  EXPECT_TRUE(j["fits"].get<bool>());
  EXPECT_EQ(j["details"]["options"], "ARB_precision_hint_fastest");
  EXPECT_EQ(j["check"]["name"], "Mesa");
  for (const char* key : {"alu", "tex", "instruction_slots", "temporaries", "parameters",
                          "attributes", "indirections", "address_registers"}) {
    const nlohmann::json f = resource(j, key);
    EXPECT_TRUE(f.contains("limit")) << key;
    EXPECT_TRUE(f["rule"].is_string()) << key;
    EXPECT_TRUE(f["check"]["agrees"].get<bool>()) << key;
  }
  // By hand: MUL is ALU, TEX is TEX, one declared temporary, one inline constant, one input.
  EXPECT_EQ(resource(j, "alu")["used"], 1);
  EXPECT_EQ(resource(j, "tex")["used"], 1);
  EXPECT_EQ(resource(j, "temporaries")["used"], 1);
  EXPECT_EQ(resource(j, "parameters")["used"], 1);
  EXPECT_EQ(resource(j, "attributes")["used"], 1);
  EXPECT_EQ(resource(j, "alu")["limit"], 64);
  EXPECT_TRUE(resource(j, "address_registers")["limit"].is_null());
  EXPECT_EQ(resource(j, "instruction_slots")["check"]["value"], 3) << "Mesa counts END";
  EXPECT_TRUE(j["over"].empty());
}

TEST(BudgetFile, OverBudgetExitsOneNamingTheLimit) {
  const test::TempDir dir;
  test::write_file(dir / "big.fp", over_ps20());
  const test::RunResult r = test::run_ltrender("budget " + (dir / "big.fp").string());
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "ltrender: check failed: budget: " + (dir / "big.fp").string() +
                       ": fragment program: ALU instructions: 65 > 64 (ps_2_0)\n");
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
  EXPECT_EQ(j["details"]["kind"], "vertex");
  EXPECT_EQ(j["profiles"][0]["name"], "vs_2_0") << "ps_2_0's partner checks a vertex program";
  // 1 instruction + the 4 DP4 of position invariance; Mesa's native count is 1 + END.
  EXPECT_EQ(resource(j, "instruction_slots")["used"], 5);
  EXPECT_EQ(resource(j, "instruction_slots")["check"]["value"], 2);
  EXPECT_EQ(j["details"]["mesa_api_instructions"], 6) << "Mesa appends the 4 DP4";
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

// Program files of the three kinds, beside the ARB ones above: a GL 1.3 combiner program of
// three stages (one over gl13-2units), and a GX program of one stage.
struct Inputs {
  test::TempDir dir;
  std::string fp = (dir / "p.fp").string(), comb = (dir / "three.comb").string(),
              gx = (dir / "one.c").string(), bad = (dir / "bad.fp").string(),
              scene = (test::source_dir() / "scenes" / "backlit_sphere.json").string();
  Inputs() {
    test::write_file(fp, kFits);
    test::write_file(comb, test::read_file(test::source_dir() / "combiners" / "lobe_vertex.comb") +
                               "\nstage 2\n  texture white\n  rgb MODULATE previous primary\n");
    test::write_file(gx, "GX_SetNumTevStages(1);\nGX_SetNumChans(1);\n");
    test::write_file(bad,
                     "!!ARBfp1.0\nTEMP a;\nMOV a, fragment.color\nMOV result.color, a;\nEND\n");
  }
};

std::set<std::string> keys(const nlohmann::json& j) {
  std::set<std::string> out;
  for (const auto& [k, v] : j.items()) out.insert(k);
  return out;
}

TEST(BudgetReport, EveryKindOfInputInOneSchema) {
  const Inputs in;
  const test::RunResult r = test::run_ltrender("budget " + in.fp + " " + in.comb + " " + in.gx +
                                               " " + in.scene + " --profile gl13-3units --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<nlohmann::json> all = test::budget_records(r.out);
  ASSERT_EQ(all.size(), 4u) << r.out;
  const std::vector<std::pair<std::string, std::string>> expected = {
      {in.fp, "arbfp"}, {in.comb, "combiners"}, {in.gx, "gx"}, {in.scene, "arbfp"}};
  const std::set<std::string> top = keys(all[0]);
  for (size_t i = 0; i < all.size(); ++i) {
    const nlohmann::json& j = all[i];
    EXPECT_EQ(keys(j), top) << "the same keys for every input: " << j.dump();
    EXPECT_EQ(j["schema"], "ltrender-budget-2");
    EXPECT_EQ(j["file"], expected[i].first);
    EXPECT_EQ(j["path"], expected[i].second);
    EXPECT_EQ(j["input"], i == 3 ? "scene" : "program");
    EXPECT_TRUE(j["fits"].get<bool>()) << j.dump();
    ASSERT_FALSE(j["items"].empty()) << j.dump();
    for (const nlohmann::json& item : j["items"]) {
      const std::string scope = item["scope"];
      EXPECT_TRUE(scope == "program" || scope == "pass" || scope == "material") << scope;
      for (const nlohmann::json& res : item["resources"]) {
        EXPECT_EQ(keys(res),
                  (std::set<std::string>{"key", "label", "used", "limit", "over", "rule", "check"}))
            << res.dump();
        EXPECT_TRUE(res["used"].is_number_integer()) << res.dump();
        EXPECT_TRUE(res["limit"].is_null() || res["limit"].is_number_integer()) << res.dump();
      }
    }
  }
  // By hand: the combiner file has three stages, against gl13-3units' three.
  EXPECT_EQ(test::budget_resource(all[1]["items"][0], "stages")["used"], 3);
  EXPECT_EQ(test::budget_resource(all[1]["items"][0], "stages")["limit"], 3);
  EXPECT_EQ(test::budget_resource(all[2]["items"][0], "tev_stages")["used"], 1);
  EXPECT_EQ(test::budget_resource(all[2]["items"][0], "tev_stages")["limit"], 16);
}

// An invalid file is a record of its own, in its turn, beside its error line (it printed none).
TEST(BudgetReport, AnInvalidFileIsAnErrorRecordUnderJson) {
  const Inputs in;
  const test::RunResult r =
      test::run_ltrender("budget " + in.fp + " " + in.bad + " " + in.gx + " --json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "ltrender: error: " + in.bad + ":4:1: expected ';', found 'MOV'\n");
  const std::vector<nlohmann::json> all = test::budget_records(r.out);
  ASSERT_EQ(all.size(), 3u) << r.out;
  const nlohmann::json& e = all[1];
  EXPECT_EQ(e["schema"], "ltrender-budget-2");
  EXPECT_EQ(e["file"], in.bad);
  EXPECT_TRUE(e["fits"].is_null());
  EXPECT_EQ(e["error"]["file"], in.bad);
  EXPECT_EQ(e["error"]["where"], "4:1");
  EXPECT_EQ(e["error"]["message"], "expected ';', found 'MOV'");
  EXPECT_FALSE(all[0].contains("error"));
  EXPECT_EQ(all[2]["file"], in.gx);
}

// Every line of the text names the file it reports on, and so does the failure line.
TEST(BudgetReport, EveryTextLineNamesItsFile) {
  const Inputs in;
  const test::RunResult r = test::run_ltrender("budget " + in.fp + " " + in.comb + " " + in.gx);
  EXPECT_EQ(r.exit_code, 1) << r.err;
  EXPECT_EQ(r.err, "ltrender: check failed: budget: " + in.comb +
                       ": program lobe_vertex: stages: 3 > 2 (gl13-2units)\n");
  std::map<std::string, int> lines;
  std::istringstream out(r.out);
  for (std::string line; std::getline(out, line);) {
    std::string file;
    for (const std::string& f : {in.fp, in.comb, in.gx}) {
      if (line.rfind(f + ": ", 0) == 0) file = f;
    }
    EXPECT_FALSE(file.empty()) << "a line that names no file: " << line;
    ++lines[file];
  }
  EXPECT_GE(lines[in.fp], 3);
  EXPECT_GE(lines[in.comb], 3);
  EXPECT_GE(lines[in.gx], 3);
  EXPECT_NE(r.out.find(in.comb + ": OVER program lobe_vertex: stages: 3 > 2 (gl13-2units)\n"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("combiners//"), std::string::npos) << r.out;
}

// --profile names one profile per kind of input, each going to the path that has it.
TEST(BudgetReport, AProfilePerKindOfInput) {
  const Inputs in;
  const std::string both = "budget " + in.comb + " " + in.fp;
  // gl13-3units is the combiners path's: the .comb file fits it, the ARB file keeps ps_2_0.
  const test::RunResult one = test::run_ltrender(both + " --profile gl13-3units --json");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const std::vector<nlohmann::json> a = test::budget_records(one.out);
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0]["profiles"][0]["name"], "gl13-3units");
  EXPECT_EQ(a[1]["profiles"][0]["name"], "ps_2_0");
  for (const std::string& two : {std::string(" --profile gl13-3units,arbfp1-min"),
                                 std::string(" --profile arbfp1-min --profile gl13-3units")}) {
    const test::RunResult r = test::run_ltrender(both + two + " --json");
    ASSERT_EQ(r.exit_code, 0) << two << ": " << r.err;
    const std::vector<nlohmann::json> b = test::budget_records(r.out);
    ASSERT_EQ(b.size(), 2u);
    EXPECT_EQ(b[0]["profiles"][0]["name"], "gl13-3units") << two;
    EXPECT_EQ(b[1]["profiles"][0]["name"], "arbfp1-min") << two;
  }
  // Refused before anything is counted: two of one kind, an unknown one (named with the
  // profiles of each kind), one for a kind no input has.
  const test::RunResult twice = test::run_ltrender(both + " --profile ps_2_0,ps_2_x");
  EXPECT_EQ(twice.exit_code, 2);
  EXPECT_EQ(twice.err,
            "ltrender: error: --profile:ps_2_x: a second arbfp profile (ps_2_0 is given "
            "too): one profile per kind of input\n");
  EXPECT_EQ(twice.out, "");
  const test::RunResult unknown = test::run_ltrender(both + " --profile gl13-4units");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_EQ(unknown.err,
            "ltrender: error: --profile:gl13-4units: unknown profile (arbfp: ps_2_0, ps_2_x, "
            "arbfp1-min, vs_2_0, arbvp1-min, ps_2_a, ps_2_b, ps_3_0, vs_1_1, vs_3_0; combiners: "
            "gl13-2units, gl13-3units, gl-8units; gx: wii-tev)\n");
  const test::RunResult none = test::run_ltrender(both + " --profile wii-tev");
  EXPECT_EQ(none.exit_code, 2);
  EXPECT_EQ(none.err,
            "ltrender: error: --profile:wii-tev: a profile of gx, which counts none of "
            "the inputs (" +
                in.fp + ": arbfp, " + in.comb + ": combiners)\n");
  EXPECT_EQ(none.out, "");
}

// --path names the path that counts scenes: used for a scene, refused beside a program file of
// another path (it was silently ignored).
TEST(BudgetReport, PathIsUsedOrRefused) {
  const Inputs in;
  const test::RunResult refused = test::run_ltrender("budget " + in.fp + " --path gx");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_EQ(refused.err,
            "ltrender: error: " + in.fp +
                ":--path: a program file of arbfp, which "
                "counts it; --path gx counts scenes (leave --path out, or name arbfp)\n");
  EXPECT_EQ(refused.out, "");
  EXPECT_EQ(test::run_ltrender("budget " + in.fp + " --path arbfp").exit_code, 0);
  const test::RunResult scene = test::run_ltrender("budget " + in.scene + " --path gx --json");
  ASSERT_EQ(scene.exit_code, 0) << scene.err;
  EXPECT_EQ(nlohmann::json::parse(scene.out)["path"], "gx");
}

}  // namespace
}  // namespace lt
