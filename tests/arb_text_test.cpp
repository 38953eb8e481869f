// Hand-written ARB programs through the text parser and counter (arb_text_parser.h,
// arb_counter.h) and through Mesa: valid programs with counts worked out by hand from the specs'
// rules (and Mesa's parameter layout), each also loaded by Mesa whose GL_PROGRAM_NATIVE_*
// figures must be what the rules predict; invalid programs with the position and the message
// the parser must give, each refused by Mesa too.
#include <gtest/gtest.h>

#include "arb_text_cases.h"
#include "gl/context.h"
#include "paths/arbfp/arb_counter.h"
#include "paths/arbfp/arb_mesa_counts.h"
#include "paths/arbfp/arb_text_parser.h"

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
