// Fuzzed program text: seeded mutations of valid and invalid ARB programs (hand-written ones and
// the generator's) through `budget FILE`. Every case must end as 0 (fits), 1 (over) or 2 (not a
// valid program, an InputError naming file:line:column), never another exception, a crash or a
// hang; where both our parser and Mesa accept a mutant, every figure must be what its rule
// predicts from Mesa's. The run is a fixed few hundred cases (a few seconds); a hang is caught by
// ctest's timeout, not by a wall-clock assertion, which failed on a loaded machine.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <random>

#include "arb_test_util.h"
#include "arb_text_cases.h"
#include "core/error.h"
#include "gl/context.h"
#include "arb/arb_counter.h"
#include "budget/arb_file_budget.h"
#include "paths/arbfp/arb_generator.h"

namespace lt {
namespace {

std::vector<std::string> seeds() {
  std::vector<std::string> out;
  for (const test::Valid& v : test::kValid) out.push_back(v.source);
  for (const test::Invalid& v : test::kInvalid) out.push_back(v.source);
  const Scene scene = test::load_test_scene("scenes/three_point_blob.json");
  for (const char* variant : {"pow=mul", "pow=lut:256:u8", "pow=mul:vertex"}) {
    const auto p =
        arbfp::generate_arb(scene, scene.materials.front(), arbfp::parse_variant(variant));
    out.push_back(p.vertex);
    out.push_back(p.fragment);
  }
  // One over ps_2_0's 64 ALU instructions, so mutants end as 1 too.
  std::string over = "!!ARBfp1.0\nTEMP a;\nMOV a, fragment.color;\n";
  for (int i = 0; i < 64; ++i) over += "ADD a, a, {0.5, 0.25, 1, 2};\n";
  out.push_back(over + "MOV result.color, a;\nEND\n");
  return out;
}

// Pieces of program text a mutation inserts: punctuation, keywords, bindings, numbers at and
// past every limit, and bytes that are no token.
const char* const kPieces[] = {
    ";",           ",",
    ".",           "[",
    "]",           "{",
    "}",           "-",
    "..",          "x",
    "xyzw",        "0",
    "1.5",         "1e99",
    "TEMP",        "PARAM",
    "MOV",         "TEX",
    "KIL",         "SWZ",
    "END",         "#",
    "\n",          "ALIAS a = ",
    "OPTION ",     "texture[",
    "texture[99]", "state.matrix.mvp",
    "state.",      "program.env[",
    "fragment.",   "vertex.attrib[",
    "result.",     "99999999999",
    "\x01",        "\xff",
    "_SAT",        "A0.x",
    "[A0.x + 1]",
};

std::string mutate_program(std::string s, std::mt19937& rng) {
  auto pick = [&rng](size_t n) {
    return n ? std::uniform_int_distribution<size_t>(0, n - 1)(rng) : 0;
  };
  // Mostly one mutation, so that a fair share of mutants stays valid and reaches Mesa.
  const int mutations = pick(2) ? 1 : 2 + static_cast<int>(pick(2));
  for (int m = 0; m < mutations; ++m) {
    const size_t at = pick(s.size() + 1);
    switch (pick(6)) {
      case 0:  // delete a few bytes
        s.erase(std::min(at, s.size()), 1 + pick(8));
        break;
      case 1:  // insert a piece
        s.insert(std::min(at, s.size()), kPieces[pick(sizeof kPieces / sizeof kPieces[0])]);
        break;
      case 2:  // one byte, any value
        if (!s.empty()) s[std::min(at, s.size() - 1)] = static_cast<char>(pick(256));
        break;
      case 3: {  // duplicate a line
        const size_t start = s.rfind('\n', at == 0 ? 0 : at - 1);
        const size_t from = start == std::string::npos ? 0 : start + 1;
        const size_t end = s.find('\n', from);
        s.insert(from,
                 s.substr(from, end == std::string::npos ? std::string::npos : end - from + 1));
        break;
      }
      case 4:  // swap two bytes far apart
        if (s.size() > 1) std::swap(s[std::min(at, s.size() - 1)], s[pick(s.size())]);
        break;
      default:  // truncate
        s.resize(std::min(at, s.size()));
        break;
    }
  }
  return s;
}

TEST(ArbTextFuzz, MutatedProgramsEndAsZeroOneOrTwo) {
  const std::vector<std::string> corpus = seeds();
  std::mt19937 rng(10);  // fixed: the same cases every run
  const test::TempDir dir;
  int outcomes[3] = {0, 0, 0};
  int stricter_than_mesa = 0;  // refused by the parser, accepted by Mesa
  int laxer_than_mesa = 0;     // accepted by the parser, refused by Mesa (still exit 2)
  const auto start = std::chrono::steady_clock::now();
  // LT_ARB_FUZZ_CASES=N (and LT_ARB_FUZZ_SEED) run a longer search by hand; the suite runs 400.
  const char* env_cases = std::getenv("LT_ARB_FUZZ_CASES");
  const char* env_seed = std::getenv("LT_ARB_FUZZ_SEED");
  const int kCases = env_cases ? std::atoi(env_cases) : 400;
  if (env_seed) rng.seed(static_cast<unsigned>(std::atoi(env_seed)));
  for (int i = 0; i < kCases; ++i) {
    const std::string text = mutate_program(
        corpus[std::uniform_int_distribution<size_t>(0, corpus.size() - 1)(rng)], rng);
    const std::string file = (dir / ("case" + std::to_string(i) + ".arb")).string();
    test::write_file(file, text);
    try {
      const budget::Report b = arbfp::budget_arb_file(file, "");
      ++outcomes[b.fits() ? 0 : 1];
      for (const budget::Resource& f : b.items.at(0).resources) {
        EXPECT_TRUE(!f.check || f.check->agrees) << "case " << i << ": " << f.label << " " << f.used
                                                 << ", Mesa " << f.check->value << "\n"
                                                 << text;
      }
    } catch (const InputError& e) {
      ++outcomes[2];
      // file:line:column: what (or the file's own read error for bytes no reader takes).
      EXPECT_EQ(std::string(e.what()).rfind(file + ":", 0), 0u) << e.what();
      if (std::string(e.what()).find("Mesa refuses") != std::string::npos) {
        ++laxer_than_mesa;
        std::printf("parser accepts, Mesa refuses: %s\n", e.what());
        continue;
      }
      const bool vertex = text.find("!!ARBvp1.0") != std::string::npos;
      const gl::Context ctx(8, 8);
      const auto m = arbfp::mesa_counts(
          vertex ? budget::ProgramKind::Vertex : budget::ProgramKind::Fragment, text);
      if (m.accepted) {
        ++stricter_than_mesa;
        std::printf("parser refuses, Mesa accepts: %s\n", e.what());
      }
    } catch (const std::exception& e) {
      ADD_FAILURE() << "case " << i << ": " << e.what() << "\n" << text;
    }
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf(
      "%d cases: %d fit, %d over, %d invalid (%d refused by the parser only, %d by Mesa only), "
      "%.2f s\n",
      kCases, outcomes[0], outcomes[1], outcomes[2], stricter_than_mesa, laxer_than_mesa, seconds);
  EXPECT_GT(outcomes[0], 0) << "some mutants stay valid";
  EXPECT_GT(outcomes[2], 0) << "most mutants are not valid";
}

// The same kind of cases through the command line: the exit code is 0, 1 or 2, and a 2 is one
// line naming the file.
TEST(ArbTextFuzz, MutatedProgramsThroughTheCommandLine) {
  const std::vector<std::string> corpus = seeds();
  std::mt19937 rng(11);
  const test::TempDir dir;
  for (int i = 0; i < 12; ++i) {
    const std::string text = mutate_program(
        corpus[std::uniform_int_distribution<size_t>(0, corpus.size() - 1)(rng)], rng);
    const std::string file = (dir / ("case" + std::to_string(i) + ".fp")).string();
    test::write_file(file, text);
    const test::RunResult r = test::run_ltrender("budget " + file);
    EXPECT_TRUE(r.exit_code == 0 || r.exit_code == 1 || r.exit_code == 2) << r.exit_code;
    if (r.exit_code == 2) {
      EXPECT_EQ(r.err.rfind("ltrender: error: " + file + ":", 0), 0u) << r.err;
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    }
  }
}

}  // namespace
}  // namespace lt
