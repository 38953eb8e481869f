// The ARB programs as instruction lists (arb/arb_ir.h): printing, the checks against
// what the specs reject, the counts of a program against those of its printed text parsed back
// (arb_text_parser.h), and a dump of every generated program for byte-identity checks.
#include "arb/arb_ir.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <map>

#include "arb_cases.h"
#include "core/error.h"
#include "arb/arb_counter.h"
#include "arb/arb_ir_counter.h"

namespace lt {
namespace {

using arbfp::ir::attrib;
using arbfp::ir::Op;
using arbfp::ir::output;
using arbfp::ir::Program;
using arbfp::ir::ProgramKind;
using arbfp::ir::Reg;

void expect_same_counts(const budget::ProgramCounts& a, const budget::ProgramCounts& b,
                        const std::string& what) {
  EXPECT_EQ(a.kind, b.kind) << what;
  EXPECT_EQ(a.alu, b.alu) << what;
  EXPECT_EQ(a.tex, b.tex) << what;
  EXPECT_EQ(a.temporaries, b.temporaries) << what;
  EXPECT_EQ(a.parameters, b.parameters) << what;
  EXPECT_EQ(a.attributes, b.attributes) << what;
  EXPECT_EQ(a.indirections, b.indirections) << what;
  EXPECT_EQ(a.position_invariant, b.position_invariant) << what;
}

// Blocks print in the order they were opened, whatever the order they were written in: here the
// code is written first and the declaration it reads last.
TEST(ArbIr, PrintsBlocksInOrderWithDeclarationsWhereTheyWereWritten) {
  Program p(ProgramKind::Fragment);
  arbfp::ir::Block decls = p.block(), temps = p.block(), code = p.block();
  const Reg a = p.temp("a"), b = p.temp("b");
  code.text("# code\n");
  temps.temps();
  code.op(Op::MUL, a.masked("xyz"), {attrib("fragment.texcoord[0]"), -b.swz("w")}, "why");
  const Reg k = decls.param("k", arbfp::ir::vec4(0.1, 2, 0, 1e30), "constant");
  code.op_sat(Op::DP3, b.masked("x"), {a, k});
  code.tex(b, a.swz("x"), 0, "1D");
  code.op(Op::MOV, output("result.color"), {b});
  EXPECT_EQ(arbfp::ir::print(p),
            "!!ARBfp1.0\n"
            "PARAM k = {0.100000001, 2, 0, 1.00000002e+30};  # constant\n"
            "TEMP a, b;\n"
            "# code\n"
            "MUL a.xyz, fragment.texcoord[0], -b.w;  # why\n"
            "DP3_SAT b.x, a, k;\n"
            "TEX b, a.x, texture[0], 1D;\n"
            "MOV result.color, b;\n"
            "END\n");
  const std::vector<arbfp::ir::Instr> code_list = p.instructions();
  ASSERT_EQ(code_list.size(), 4u);
  EXPECT_EQ(code_list[2].op, Op::TEX);
}

// The hand-written indirection cases of budget_test, built as IR: both counters give the spec's
// figures.
TEST(ArbIr, CountsTextureIndirectionsLikeTheTextCounter) {
  struct Case {
    const char* name;
    int tex, indirections;
    void (*build)(Program&);
  };
  const Case cases[] = {
      {"dependent_tex", 2, 2,
       [](Program& p) {
         arbfp::ir::Block b = p.block();
         const Reg a = p.temp("a"), c = p.temp("c");
         b.temps();
         b.tex(a, attrib("fragment.texcoord[0]"), 0, "2D");
         b.tex(c, a, 1, "2D");
         b.op(Op::MOV, output("result.color"), {c});
       }},
      {"tex_overwrites_alu_temp", 1, 2,
       [](Program& p) {
         arbfp::ir::Block b = p.block();
         const Reg a = p.temp("a"), c = p.temp("c");
         b.temps();
         b.op(Op::MOV, a, {attrib("fragment.color")});
         b.op(Op::MOV, c, {a});
         b.tex(a, attrib("fragment.texcoord[0]"), 0, "2D");
         b.op(Op::ADD, output("result.color"), {a, c});
       }},
      {"parallel_reads", 2, 2,
       [](Program& p) {
         arbfp::ir::Block b = p.block();
         const Reg a = p.temp("a"), c = p.temp("c"), d = p.temp("d");
         const Reg two = b.param("two", "{2, 2, 2, 2}");
         b.temps();
         b.op(Op::MUL, a, {attrib("fragment.texcoord[0]"), two});
         b.tex(c, a, 0, "2D");
         b.tex(d, a, 1, "2D");
         b.op(Op::ADD, output("result.color"), {c, d});
       }},
      {"kil", 1, 1,
       [](Program& p) {
         arbfp::ir::Block b = p.block();
         arbfp::ir::Instr kil;
         kil.op = Op::KIL;
         kil.srcs = {attrib("fragment.texcoord[0]")};
         b.emit(kil);
         b.op(Op::MOV, output("result.color"), {attrib("fragment.color")});
       }},
  };
  for (const Case& c : cases) {
    Program p(ProgramKind::Fragment);
    c.build(p);
    const budget::ProgramCounts ir = arbfp::ir::count(p);
    expect_same_counts(ir, budget::count_program(arbfp::ir::print(p)), c.name);
    EXPECT_EQ(ir.tex, c.tex) << c.name;
    EXPECT_EQ(ir.indirections, c.indirections) << c.name;
  }
}

TEST(ArbIr, VertexProgramsCountEverythingAsAluAndTheirOption) {
  Program p(ProgramKind::Vertex);
  arbfp::ir::Block b = p.block();
  b.option("ARB_position_invariant");
  b.op(Op::MOV, output("result.texcoord[0]"), {attrib("vertex.position")});
  b.op(Op::MOV, output("result.texcoord[1]"), {attrib("vertex.normal")});
  const budget::ProgramCounts c = arbfp::ir::count(p);
  expect_same_counts(c, budget::count_program(arbfp::ir::print(p)), "vertex");
  EXPECT_EQ(c.alu, 2);
  EXPECT_EQ(c.attributes, 2);
  EXPECT_TRUE(c.position_invariant);
}

// What the specs would reject stops the generator where it is written (LT_CHECK aborts).
TEST(ArbIrDeathTest, RejectsWhatTheSpecsReject) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // scene loading may have started threads
  auto vertex = [](auto write) {
    Program p(ProgramKind::Vertex);
    arbfp::ir::Block b = p.block();
    write(p, b);
  };
  EXPECT_DEATH(vertex([](Program& p, arbfp::ir::Block& b) {
                 const Reg a = p.temp("a");
                 b.op(Op::CMP, a, {a, a, a});
               }),
               "CMP is not an instruction of vertex programs");
  EXPECT_DEATH(vertex([](Program& p, arbfp::ir::Block& b) {
                 const Reg a = p.temp("a");
                 b.op_sat(Op::MOV, a, {attrib("vertex.normal")});
               }),
               "no saturation");
  EXPECT_DEATH(vertex([](Program& p, arbfp::ir::Block& b) {
                 const Reg a = p.temp("a");
                 b.op(Op::MOV, a.swz("x"), {a});
               }),
               "a destination has a mask only");
  EXPECT_DEATH(vertex([](Program& p, arbfp::ir::Block& b) {
                 const Reg a = p.temp("a");
                 b.op(Op::MUL, a, {a});
               }),
               "wrong operand count");
  EXPECT_DEATH(
      vertex([](Program&, arbfp::ir::Block& b) { b.op(Op::MOV, output("result.color"), {Reg{}}); }),
      "a source is a declared register");
  EXPECT_DEATH(vertex([](Program& p, arbfp::ir::Block& b) {
                 p.temp("a");
                 b.param("a", "{0, 0, 0, 0}");
               }),
               "declared twice");
  EXPECT_DEATH(vertex([](Program&, arbfp::ir::Block& b) { b.text("MOV a, b;\n"); }),
               "not a comment");
}

// The budget counts the generator's instruction list; a hand-written program is parsed into one.
// On every generated program of every case the printed text parses back to the same figures, and
// the text is the IR's print.
TEST(ArbIr, EveryGeneratedProgramParsesBackToTheSameCounts) {
  size_t programs = 0;
  test::for_each_arb_case([&](const test::ArbCase& c) {
    arbfp::ArbPrograms p;
    try {
      p = arbfp::generate_arb(c.scene, c.material, c.variant, c.term);
    } catch (const InputError&) {
      return;  // too many lights for pow=mul:vertex: nothing generated
    }
    EXPECT_EQ(arbfp::ir::print(p.vertex_program), p.vertex) << c.label;
    EXPECT_EQ(arbfp::ir::print(p.fragment_program), p.fragment) << c.label;
    expect_same_counts(arbfp::ir::count(p.vertex_program), budget::count_program(p.vertex),
                       c.label + " vertex");
    expect_same_counts(arbfp::ir::count(p.fragment_program), budget::count_program(p.fragment),
                       c.label + " fragment");
    programs += 2;
  });
  EXPECT_GT(programs, 10000u) << "the case list (arb_cases.h) lost most of its cases";
}

// With LT_ARB_DUMP_DIR set, writes every generated program of every case (arb_cases.h), its
// notes and LUT, one file per scene and change: the generator's output must stay byte-identical
// across refactorings, and `diff -r` of two dumps says where it does not.
TEST(ArbDump, WritesEveryProgramWhenAsked) {
  const char* dir = std::getenv("LT_ARB_DUMP_DIR");
  if (!dir) GTEST_SKIP() << "set LT_ARB_DUMP_DIR to dump every generated program";
  fs::create_directories(dir);
  std::map<std::string, std::ofstream> files;
  size_t programs = 0;
  test::for_each_arb_case([&](const test::ArbCase& c) {
    const std::string key = c.label.substr(0, c.label.find(" k="));
    auto it = files.find(key);
    if (it == files.end()) {
      it = files.emplace(key, std::ofstream(fs::path(dir) / (test::test_param_name(key) + ".txt")))
               .first;
    }
    std::ofstream& out = it->second;
    out << "=== " << c.label << "\n";
    try {
      const arbfp::ArbPrograms p = arbfp::generate_arb(c.scene, c.material, c.variant, c.term);
      out << p.vertex << "\n--- fragment\n" << p.fragment << "\n--- notes\n";
      for (const std::string& n : p.notes) out << n << "\n";
      if (p.lut) out << "--- lut " << p.lut->size << " " << model::to_string(p.lut->format) << "\n";
      programs += 2;
    } catch (const InputError& e) {
      out << "--- throws: " << e.what() << "\n";
    }
  });
  std::cout << programs << " programs in " << files.size() << " files under " << dir << "\n";
}

}  // namespace
}  // namespace lt
