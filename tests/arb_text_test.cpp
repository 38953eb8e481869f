// Hand-written ARB programs through the text parser into the instruction list and its counter
// (arb_text_parser.h, arb_ir_counter.h) and through Mesa: valid programs with counts worked out by
// hand from the specs' rules (and Mesa's parameter layout), each also loaded by Mesa whose
// GL_PROGRAM_NATIVE_* figures must be what the rules predict; invalid programs with the position
// and the message the parser must give, each refused by Mesa too.
#include <gtest/gtest.h>

#include "arb_text_cases.h"
#include "gl/context.h"
#include "arb/arb_counter.h"
#include "arb/arb_mesa_counts.h"
#include "arb/arb_text_parser.h"

namespace lt {
namespace {

using budget::ProgramCounts;
using test::Invalid;
using test::kInvalid;
using test::kValid;
using test::Valid;

TEST(ArbText, ValidProgramsHaveTheirCounts) {
  for (const Valid& v : kValid) {
    const ProgramCounts c = budget::count_program(v.source);
    EXPECT_EQ(c.alu, v.alu) << v.name;
    EXPECT_EQ(c.tex, v.tex) << v.name;
    EXPECT_EQ(c.temporaries, v.temps) << v.name;
    EXPECT_EQ(c.parameters, v.params) << v.name;
    EXPECT_EQ(c.referenced_parameters, v.referenced_params) << v.name;
    EXPECT_EQ(c.attributes, v.attribs) << v.name;
    EXPECT_EQ(c.indirections, v.indirections) << v.name;
    EXPECT_EQ(c.address_registers, v.address) << v.name;
  }
}

// Text becomes the instruction list the generator builds (arb_ir.h): opcodes, operand files,
// masks and swizzles as written, array elements (-1: relative), literals, texture units and
// targets.
TEST(ArbText, ParsesIntoTheGeneratorsInstructionList) {
  using arbfp::ir::File;
  using arbfp::ir::Op;
  const arbfp::ir::Program v = arbfp::text::parse(
      "!!ARBvp1.0\nADDRESS a;\nPARAM c[2] = { {1, 2, 3, 4}, state.matrix.mvp.row[0] };\n"
      "TEMP t;\nARL a.x, vertex.position.x;\nMOV t.xy, c[a.x + 1];\n"
      "SWZ result.position, t, 0, 1, -x, y;\nEND\n");
  EXPECT_EQ(v.kind(), budget::ProgramKind::Vertex);
  EXPECT_EQ(v.addresses(), std::vector<std::string>{"a"});
  EXPECT_EQ(v.temps(), std::vector<std::string>{"t"});
  ASSERT_EQ(v.params().size(), 1u);
  EXPECT_TRUE(v.params()[0].array);
  ASSERT_EQ(v.params()[0].slots.size(), 2u);
  EXPECT_TRUE(v.params()[0].slots[0].constant);
  EXPECT_EQ(v.params()[0].slots[0].values[3], 4.0f);
  EXPECT_EQ(v.params()[0].slots[1].binding, "state.matrix.mvp.row[0]");
  const std::vector<arbfp::ir::Instr> vi = v.instructions();
  ASSERT_EQ(vi.size(), 3u);
  EXPECT_EQ(vi[0].op, Op::ARL);
  EXPECT_EQ(vi[0].dst.file, File::Address);
  EXPECT_EQ(vi[0].dst.write_mask, "x");
  EXPECT_EQ(vi[0].srcs[0].binding, "vertex.position");
  EXPECT_EQ(vi[0].srcs[0].swizzle, "x");
  EXPECT_EQ(vi[1].dst.write_mask, "xy");
  EXPECT_EQ(vi[1].srcs[0].file, File::Param);
  EXPECT_EQ(vi[1].srcs[0].element, -1);
  EXPECT_EQ(vi[2].op, Op::SWZ);
  EXPECT_EQ(vi[2].dst.binding, "result.position");
  EXPECT_EQ(vi[2].srcs[0].swizzle, "01-xy");

  const arbfp::ir::Program f = arbfp::text::parse(
      "!!ARBfp1.0\nTEMP r;\nTEX r, fragment.texcoord[0], texture[2], 2D;\n"
      "MUL_SAT result.color, r, 0.5;\nKIL -r;\nEND\n");
  const std::vector<arbfp::ir::Instr> fi = f.instructions();
  ASSERT_EQ(fi.size(), 3u);
  EXPECT_EQ(fi[0].op, Op::TEX);
  EXPECT_EQ(fi[0].texture_unit, 2);
  EXPECT_EQ(fi[0].texture_target, "2D");
  EXPECT_TRUE(fi[1].saturate);
  EXPECT_EQ(fi[1].srcs[1].file, File::Literal);
  EXPECT_EQ(fi[1].srcs[1].literal.size, 1);
  EXPECT_EQ(fi[1].srcs[1].literal.values[0], 0.5f);
  EXPECT_EQ(fi[2].op, Op::KIL);
  EXPECT_TRUE(fi[2].srcs[0].negate);
}

// Mesa's native figures are the program as written: END is one more instruction; parameters
// follow its layout; indirections are not computed (0).
TEST(ArbText, ValidProgramsAgreeWithMesa) {
  const gl::Context ctx(8, 8);
  for (const Valid& v : kValid) {
    const ProgramCounts c = budget::count_program(v.source);
    const arbfp::MesaCounts m = arbfp::mesa_counts(c.kind, v.source);
    ASSERT_TRUE(m.accepted) << v.name << ": " << m.error;
    EXPECT_EQ(m.native.instructions, v.alu + v.tex + 1) << v.name;
    EXPECT_EQ(m.native.temporaries, v.temps) << v.name;
    EXPECT_EQ(m.native.parameters, v.referenced_params) << v.name;
    EXPECT_EQ(m.native.attributes, v.attribs) << v.name;
    EXPECT_EQ(m.native.address_registers, v.address) << v.name;
    if (c.kind == budget::ProgramKind::Fragment) {
      EXPECT_EQ(m.native.alu, v.alu) << v.name;
      EXPECT_EQ(m.native.tex, v.tex) << v.name;
      EXPECT_EQ(m.native.indirections, 0) << v.name;
    }
    if (c.position_invariant) {
      EXPECT_EQ(m.api.instructions, m.native.instructions + 4) << v.name << ": the 4 DP4";
    }
  }
}

// Line and column (1-based) of the first occurrence of `needle`; the end of the text for "".
arbfp::text::Position position_of(const std::string& source, const std::string& needle) {
  const size_t at = needle.empty() ? source.size() : source.find(needle);
  arbfp::text::Position p;
  for (size_t i = 0; i < at && i < source.size(); ++i) {
    if (source[i] == '\n') {
      ++p.line;
      p.column = 1;
    } else {
      ++p.column;
    }
  }
  return p;
}

TEST(ArbText, InvalidProgramsNameTheirPosition) {
  for (const Invalid& v : kInvalid) {
    const std::string source = v.source;
    ASSERT_TRUE(v.at[0] == '\0' || source.find(v.at) != std::string::npos) << v.name;
    const arbfp::text::Position want = position_of(source, v.at);
    try {
      arbfp::text::parse(source);
      ADD_FAILURE() << v.name << ": parsed";
    } catch (const arbfp::text::SyntaxError& e) {
      EXPECT_EQ(e.at().line, want.line) << v.name << ": " << e.what();
      EXPECT_EQ(e.at().column, want.column) << v.name << ": " << e.what();
      EXPECT_NE(e.message().find(v.message), std::string::npos) << v.name << ": " << e.what();
    }
  }
}

// What the parser refuses, Mesa refuses too (it names its own position, which may differ: Mesa
// stops at the first token its grammar cannot take, the parser at the one that breaks a rule).
TEST(ArbText, InvalidProgramsAreRefusedByMesa) {
  const gl::Context ctx(8, 8);
  for (const Invalid& v : kInvalid) {
    const std::string source = v.source;
    const bool vertex = source.find("!!ARBvp1.0") != std::string::npos;
    const arbfp::MesaCounts m = arbfp::mesa_counts(
        vertex ? budget::ProgramKind::Vertex : budget::ProgramKind::Fragment, source);
    EXPECT_FALSE(m.accepted) << v.name;
  }
}

}  // namespace
}  // namespace lt
