// The Direct3D 9 assembly reader and counter (d3d9/d3d9_asm_*.h) on programs written for
// the test: each expected figure is summed by hand from the documentation's instruction tables
// (the slots each comment names), never read back from the counter; and every refusal names its
// line and column.
#include <gtest/gtest.h>

#include "arb/arb_text_lexer.h"
#include "d3d9/d3d9_asm_counter.h"
#include "d3d9/d3d9_asm_parser.h"
#include "d3d9/d3d9_fxc_comment.h"

namespace lt {
namespace {

d3d9::Counts counted(const std::string& source) {
  return d3d9::count(d3d9::parse(source));
}

TEST(D3d9Asm, Vs11MacrosTakeTheirTablesSlots) {
  const d3d9::Counts c = counted(
      "vs_1_1\n"
      "dcl_position v0\n"
      "def c10, 1, 0, 0.5, 0\n"  // 0
      "m4x4 oPos, v0, c0\n"      // 4, reading c0..c3
      "exp r0, v0.x\n"           // 10: vs_1_1's full-precision macro
      "frc r1.xy, v0\n"          // 3: vs_1_1's macro
      "mov oD0, r0\n");          // 1
  EXPECT_EQ(c.arithmetic, 18);
  EXPECT_EQ(c.texture, 0);
  EXPECT_EQ(c.slots(), 18);
  EXPECT_EQ(c.temporaries, 2);  // r0, r1
  EXPECT_EQ(c.constants, 11);   // c0..c10
  EXPECT_EQ(c.inputs, 1);       // v0
}

TEST(D3d9Asm, AMatrixMacroReadsItsRows) {
  EXPECT_EQ(counted("vs_2_0\nm4x3 r0.xyz, v0, c8\nmov oPos, r0\n").constants, 11);  // c8..c10
  EXPECT_EQ(counted("vs_2_0\nm3x2 r0.xy, v0, r4\nmov oPos, r0\n").temporaries, 6);  // r4, r5
}

TEST(D3d9Asm, Vs20SlotsAsFxcCountsThem) {
  const d3d9::Counts c = counted(
      "vs_2_0\n"
      "dcl_position v0\n"
      "m4x4 oPos, v0, c0\n"             // 4
      "exp r0, v0.x\n"                  // 1 from vs_2_0 on
      "frc r1.xy, v0\n"                 // 3, as fxc counts (the table says 1)
      "sincos r2.xy, v0.x, c11, c12\n"  // 8
      "nrm r3.xyz, v0\n"                // 3
      "mov oT0, r3\n");                 // 1
  EXPECT_EQ(c.arithmetic, 20);
  EXPECT_EQ(c.temporaries, 4);
  EXPECT_EQ(c.constants, 13);
}

TEST(D3d9Asm, Ps20SplitsAluFromTexAndCountsDependentLevels) {
  const d3d9::Counts c = counted(
      "ps_2_0\n"
      "dcl t0.xy\n"
      "dcl_2d s0\n"
      "dcl_2d s1\n"
      "texld r0, t0, s0\n"           // TEX 1, not dependent (order 0)
      "texld r1, r0, s1\n"           // TEX 1, first order: src0 is an r#
      "mad r2, r1, c0, c1\n"         // ALU 1, r2 depends on a first-order read
      "texld_pp r3, r2, s0\n"        // TEX 1, second order
      "lrp r4, r3, r1, r0\n"         // ALU 2
      "pow r5.x, r4.x, c2.x\n"       // ALU 3
      "texkill r5\n"                 // TEX 1
      "mov_sat oC0, r4 // done\n");  // ALU 1
  EXPECT_EQ(c.arithmetic, 7);
  EXPECT_EQ(c.texture, 4);
  EXPECT_EQ(c.dependent_levels, 3);  // orders 0, 1, 2
  EXPECT_EQ(c.temporaries, 6);
  EXPECT_EQ(c.constants, 3);
  EXPECT_EQ(c.samplers, 2);
  EXPECT_EQ(c.inputs, 1);  // t0
}

// "texld - ps_2_0 and up": rewriting a destination makes a read first-order dependent too, and
// writing into a register that holds a first-order result makes it second order.
TEST(D3d9Asm, ARewrittenDestinationIsADependentRead) {
  EXPECT_EQ(counted("ps_2_0\ndcl t0\ndcl_2d s0\ntexld r0, t0, s0\nmov oC0, r0\n").dependent_levels,
            1);
  EXPECT_EQ(counted("ps_2_0\ndcl t0\ndcl t1\ndcl_2d s0\ntexld r0, t0, s0\n"
                    "texld r0, t1, s0\ntexld r0, t1, s0\nmov oC0, r0\n")
                .dependent_levels,
            3);
  EXPECT_EQ(counted("ps_2_0\nmov oC0, c0\n").dependent_levels, 0);
}

TEST(D3d9Asm, Model3AndFlowControl) {
  const d3d9::Counts c = counted(
      "ps_3_0\n"
      "defi i0, 4, 0, 1, 0\n"
      "dcl_texcoord0_centroid v0.xy\n"
      "dcl_2d s0\n"
      "rep i0\n"                        // flow 3
      "  texldl r0, v0, s0\n"           // TEX 2
      "  add r1, -r0_abs, c[aL + 2]\n"  // ALU 1 (ps_3_0 has _abs and aL)
      "  break_gt r1.x, c0.x\n"         // flow 3 (break_comp)
      "endrep\n"                        // flow 2
      "(p0.x) sincos r2.xy, r1.x\n"     // ALU 8, one source in 3_0
      "mov oC0, r2\n");                 // ALU 1
  EXPECT_EQ(c.arithmetic, 10);
  EXPECT_EQ(c.texture, 2);
  EXPECT_EQ(c.flow, 8);
  EXPECT_EQ(c.slots(), 20);
  EXPECT_TRUE(c.relative_constants);
}

TEST(D3d9Asm, FirstCodeLineNamesTheText) {
  EXPECT_TRUE(d3d9::starts_with_version("// fxc /Tps_2_0\n\n    ps_2_0\n    mov oC0, c0\n"));
  EXPECT_TRUE(d3d9::starts_with_version("; 1 ALU\nvs_3_0\n"));
  EXPECT_TRUE(d3d9::starts_with_version("ps_1_4\n"));  // read only to be refused by name
  EXPECT_FALSE(d3d9::starts_with_version("!!ARBfp1.0\nEND\n"));
  EXPECT_FALSE(d3d9::starts_with_version("GX_SetNumTevStages(1);\n"));
}

TEST(D3d9Asm, FxcCommentsInBothForms) {
  const auto unity = d3d9::fxc_count("ps_2_0\n; 28 ALU, 4 TEX\nmov oC0, c0\n");
  ASSERT_TRUE(unity);
  EXPECT_EQ(unity->arithmetic, 28);
  EXPECT_EQ(unity->texture, 4);
  const auto listing = d3d9::fxc_count(
      "    ps_2_0\n// approximately 31 instruction slots used (4 texture, 27 "
      "arithmetic)\n");
  ASSERT_TRUE(listing);
  EXPECT_EQ(listing->slots, 31);
  EXPECT_EQ(listing->arithmetic, 27);
  EXPECT_EQ(listing->texture, 4);
  EXPECT_FALSE(d3d9::fxc_count("vs_2_0\nmov oPos, v0\n"));
}

struct Refusal {
  const char* source;
  int line, column;
  const char* message_start;
};

TEST(D3d9Asm, RefusalsNameLineAndColumn) {
  const Refusal cases[] = {
      {"ps_2_0\nmov r0, c40\n", 2, 9, "c40 is past ps_2_0's 32 constant registers (c0-c31)"},
      {"ps_2_0\nmov r12, c0\n", 2, 5, "r12 is past ps_2_0's 12 temporary registers (r0-r11)"},
      {"vs_2_0\nfoo r0, r1\n", 2, 1, "unknown instruction 'foo'"},
      {"ps_2_0\ntexldl r0, t0, s0\n", 2, 1,
       "'texldl' is not a ps_2_0 instruction (it is in vs_3_0, ps_3_0)"},
      {"ps_2_0\nadd r0, r1_abs, c0\n", 2, 9, "the source modifier _abs is shader model 3's"},
      {"vs_2_0\nmov_sat r0, v0\n", 2, 1, "_sat is not in vs_2_0"},
      {"vs_2_0\nmov r0, t0\n", 2, 9, "register type 't' (texture coordinate) is not in vs_2_0"},
      {"ps_1_4\ntexld r0, t0\n", 1, 1, "pixel shader ps_1_4 is not read"},
      {"// a listing\nps_4_0\n", 2, 1, "unknown version 'ps_4_0'"},
      {"mov r0, c0\n", 1, 1, "expected a version token, found 'mov'"},
      {"ps_2_0\nmad r0, r1, ", 2, 13, "expected a register, found the end of the line"},
      {"ps_2_0\nmad r0, r1\n", 2, 11,
       "expected ',' and a source operand, found the end of the line"},
      {"ps_2_0\nmad r0, r1, c", 2, 13, "expected an index after 'c' (c0 to c31)"},
      {"ps_2_0\nmov r0, c0, c1\n", 2, 11, "expected the end of the instruction, found ','"},
      {"vs_2_0\ndef c0, 1, 2, x, 4\n", 2, 15, "expected a number, found 'x'"},
      {"// nothing here\n", 2, 1, "expected a version token"},
      {"\x00\x02\xff\xff\x01\x00", 1, 1, "D3D9 shader bytecode (ps_2_0), not assembly text"},
  };
  for (const Refusal& c : cases) {
    // The bytecode case has NULs: its length is its array's, not strlen's.
    const std::string source = c.source[0] == '\0' ? std::string(c.source, 6) : c.source;
    try {
      d3d9::parse(source);
      ADD_FAILURE() << "accepted: " << source;
    } catch (const arbfp::text::SyntaxError& e) {
      EXPECT_EQ(e.at().line, c.line) << source << " -> " << e.what();
      EXPECT_EQ(e.at().column, c.column) << source << " -> " << e.what();
      EXPECT_EQ(e.message().rfind(c.message_start, 0), 0u) << source << " -> " << e.message();
    }
  }
}

}  // namespace
}  // namespace lt
