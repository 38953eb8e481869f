// Hand-written ARB programs for the text parser's tests (arb_text_test.cpp) and the fuzz test's
// seeds (arb_text_fuzz_test.cpp): valid ones with their counts worked out by hand, invalid ones
// with the text the error must point at.
#pragma once

namespace lt::test {

struct Valid {
  const char* name;
  const char* source;
  int alu, tex, temps, params, referenced_params, attribs, indirections, address;
};

// Each count by hand: ALU/TEX per instruction; params = declared slots + distinct inline
// constants/bindings; referenced = Mesa's layout (referenced slots, a relative array whole,
// constants merged, scalars packed); indirections by ARB_fragment_program issue 24.
inline const Valid kValid[] = {
    {"every fragment ALU opcode",
     "!!ARBfp1.0\nOPTION ARB_precision_hint_nicest;\nTEMP a, b;\n"
     "ABS a, fragment.color;\nADD a, a, fragment.color.secondary;\nCMP a, -a, a, fragment.color;\n"
     "COS b.x, a.x;\nDP3 b.y, a, a;\nDP4 b.z, a, a;\nDPH b.w, a, a;\nDST b, a, b;\n"
     "EX2 a.x, b.y;\nFLR a, a;\nFRC a, a;\nLG2 a.y, b.x;\nLIT b, a;\nLRP_SAT a, b, a, b;\n"
     "MAD a, a, b, a;\nMAX a, a, b;\nMIN a, a, b;\nMOV b, a.wzyx;\nMUL a, a, b;\n"
     "POW a.x, a.x, b.y;\nRCP a.y, a.x;\nRSQ a.z, a.y;\nSCS b.xy, a.z;\nSGE a, a, b;\n"
     "SIN a.w, b.x;\nSLT a, a, b;\nSUB a, a, b;\nSWZ b, a, 0, 1, -x, +y;\nXPD b.xyz, a, b;\n"
     "MOV result.color.rgb, b.bgra;\nEND\n",
     30, 0, 2, 0, 0, 2, 1, 0},
    // TXB reads a (written since the start): node 2; KIL reads c, just written: node 3; the
    // last TEX reads c, written by ADD: node 4. The fog option adds no instruction of its own
    // here (Mesa's API count does).
    {"texture instructions, KIL and fog",
     "!!ARBfp1.0\nOPTION ARB_fog_exp2;\nTEMP a, b, c;\n"
     "TEX a, fragment.texcoord[0], texture[0], 2D;\nTXP b, fragment.texcoord[1], texture[1], "
     "CUBE;\nTXB c, a, texture[2], 3D;\nKIL -c;\nADD c, c, b;\nTEX a, c.xyzw, texture, 2D;\n"
     "MOV result.color, a;\nMOV result.depth.z, c.x;\nEND\n",
     3, 5, 3, 0, 0, 2, 4, 0},
    // Declared: c 3 + m 5 (a matrix is 4 rows) + k 1 + unused 1 = 10; inline:
    // state.light[0].diffuse, 0.25, {0.25, 3}, program.env[7] = 4. Referenced: local[0],
    // local[2], mvp.row[1], light diffuse, k, 0.25 (k is full: a slot of its own), m[4] =
    // (1, 2, 0, 1), (0.25, 3, 0, 1), env[7] once = 9. ATTRIB never is not read.
    {"parameters, arrays, bindings, ATTRIB and ALIAS",
     "!!ARBfp1.0\nPARAM c[3] = { program.local[0..2] };\nPARAM m[] = { state.matrix.mvp, {1, 2} "
     "};\nPARAM k = 0.5;\nPARAM unused = state.fog.color;\nATTRIB uv = fragment.texcoord[2];\n"
     "ATTRIB never = fragment.position;\nTEMP t;\nALIAS u = t;\nMAD t, uv, c[0], c[2];\n"
     "DP4 u.x, m[1], state.light[0].diffuse;\nMAD t, t, k, 0.25;\nADD t, t, m[4];\n"
     "MUL t, t, {0.25, 3};\nMUL t, t, program.env[7];\nMUL t, t, program.env[7];\n"
     "MOV result.color, u;\nEND\n",
     8, 0, 1, 14, 9, 1, 1, 0},
    // Declared: mv 4 + pal 3 = 7, inline texgen, clip, point size = 3. Referenced: pal whole
    // (relative addressing) 3, mv[0], texgen, clip, point size = 7.
    {"vertex program: ARL, relative addressing, SWZ, EXP, LOG, DST, state",
     "!!ARBvp1.0\nOPTION ARB_position_invariant;\nPARAM mv[4] = { state.matrix.modelview };\n"
     "PARAM pal[] = { {1, 2, 3, 4}, {5, 6, 7, 8}, program.env[3] };\nADDRESS A0;\nTEMP t, s;\n"
     "ARL A0.x, vertex.attrib[1].x;\nMOV t, pal[A0.x + 1];\n"
     "DP4 result.texcoord[0].x, mv[0], vertex.position;\nADD result.texcoord[1], t, "
     "vertex.normal;\nSWZ result.color, vertex.color, 1, -x, 0, w;\nEXP s, vertex.position.x;\n"
     "LOG s.xy, t.w;\nMOV result.color.back.secondary, state.texgen[1].eye.s;\n"
     "MOV result.fogcoord.x, state.clip[0].plane.w;\nMOV result.pointsize.x, "
     "state.point.size.x;\nDST s, t, s;\nEND\n",
     11, 0, 2, 10, 7, 4, 1, 1},
    {"shadow target, RECT, OUTPUT, rgba masks",
     "!!ARBfp1.0\nOPTION ARB_fragment_program_shadow;\nOPTION ARB_precision_hint_fastest;\n"
     "OUTPUT out = result.color;\nTEMP a;\nTEX a, fragment.texcoord[3], texture[5], SHADOW2D;\n"
     "TXP a, fragment.texcoord[4], texture[6], RECT;\nMUL out.rgb, a, state.texenv[5].color;\n"
     "MOV out.a, state.depth.range.x;\nEND\n",
     2, 2, 1, 2, 2, 2, 1, 0},
    // Six distinct inline constants; Mesa packs 5, 6, 7, 8 into one slot, {1, 2, 3, 4} takes
    // one and 9 finds no free component: 3.
    {"scalar literals packed",
     "!!ARBfp1.0\nMAD result.color, fragment.color, 5, 6;\nMAD result.color, fragment.color, 7, "
     "8;\nMAD result.color, fragment.color, {1, 2, 3, 4}, 9;\nEND\n",
     3, 0, 0, 6, 3, 1, 1, 0},
    {"comments, white space, numbers",
     "  !!ARBfp1.0 # header\n# a comment; with a semicolon\nTEMP a;MOV a,fragment.color;\n"
     "MUL a, a, {1.5e2, .5, 5., -2};\nMOV result.color, -a;\nEND # done\n",
     3, 0, 1, 1, 1, 1, 1, 0},
};

struct Invalid {
  const char* name;
  const char* source;
  const char* at;  // the text the error must point at (its first occurrence)
  const char* message;
};

inline const Invalid kInvalid[] = {
    {"missing ';'", "!!ARBfp1.0\nTEMP a;\nMOV a, fragment.color\nMOV result.color, a;\nEND\n",
     "MOV result", "expected ';', found 'MOV'"},
    {"no header", "MOV result.color, fragment.color;\nEND\n", "MOV", "expected the header"},
    // A Windows editor's mark: Mesa reads a byte >= 0x80 as the end of the text.
    {"byte-order mark", "\xEF\xBB\xBF!!ARBfp1.0\nMOV result.color, fragment.color;\nEND\n",
     "\xEF\xBB\xBF", "a UTF-8 byte-order mark stands before the header"},
    {"undeclared name", "!!ARBfp1.0\nMOV result.color, b;\nEND\n", "b;",
     "expected a declared name, found 'b'"},
    {"declared twice", "!!ARBfp1.0\nTEMP a;\nTEMP a;\nMOV result.color, a;\nEND\n", "a;\nMOV",
     "already declared at line 2, column 6"},
    {"scalar operand without suffix", "!!ARBfp1.0\nTEMP a;\nRCP a, fragment.color;\nEND\n",
     ";\nEND", "expected a scalar suffix"},
    {"write mask out of order", "!!ARBfp1.0\nTEMP a;\nMOV a.yx, fragment.color;\nEND\n", "yx",
     "expected a write mask"},
    {"two-component swizzle", "!!ARBfp1.0\nTEMP a;\nMOV a, fragment.color.xy;\nEND\n", "xy;",
     "one or four components"},
    {"xyzw and rgba mixed in SWZ",
     "!!ARBfp1.0\nSWZ result.color, fragment.color, -1, +y, 0, r;\nEND\n", "r;", "not both"},
    {"two precision hints",
     "!!ARBfp1.0\nOPTION ARB_precision_hint_fastest;\nOPTION ARB_precision_hint_nicest;\n"
     "MOV result.color, fragment.color;\nEND\n",
     "ARB_precision_hint_nicest", "at most one ARB_precision_hint_*"},
    {"two fog options",
     "!!ARBfp1.0\nOPTION ARB_fog_exp;\nOPTION ARB_fog_linear;\nMOV result.color, "
     "fragment.color;\nEND\n",
     "ARB_fog_linear", "at most one ARB_fog_*"},
    {"unknown option", "!!ARBfp1.0\nOPTION ARB_nonsense;\nMOV result.color, fragment.color;\nEND\n",
     "ARB_nonsense", "expected an option of ARB_fragment_program"},
    {"OPTION after an instruction",
     "!!ARBfp1.0\nMOV result.color, fragment.color;\nOPTION ARB_fog_exp;\nEND\n", "OPTION",
     "OPTION must come first"},
    {"CMP in a vertex program",
     "!!ARBvp1.0\nCMP result.position, vertex.position, vertex.position, vertex.position;\nEND\n",
     "CMP", "CMP is ARB_fragment_program's"},
    {"_SAT in a vertex program", "!!ARBvp1.0\nMOV_SAT result.position, vertex.position;\nEND\n",
     "MOV_SAT", "no _SAT in vertex programs"},
    {"ARL in a fragment program", "!!ARBfp1.0\nARL a.x, fragment.color.x;\nEND\n", "ARL",
     "ARL is ARB_vertex_program's"},
    {"array index out of bounds",
     "!!ARBfp1.0\nPARAM c[3] = { program.local[0..2] };\nMOV result.color, c[3];\nEND\n", "3];",
     "expected an index below 3"},
    {"array size and initialiser differ",
     "!!ARBfp1.0\nPARAM c[2] = { program.local[0..2] };\nMOV result.color, c[0];\nEND\n",
     "2] =", "expected 3 as the array size"},
    {"one unit, two targets",
     "!!ARBfp1.0\nTEMP a;\nTEX a, fragment.texcoord[0], texture[0], 2D;\n"
     "TEX a, fragment.texcoord[0], texture[0], 3D;\nMOV result.color, a;\nEND\n",
     "3D", "expected target 2D for texture[0]"},
    {"writing an input", "!!ARBfp1.0\nMOV fragment.color, fragment.color;\nEND\n",
     "fragment.color,", "expected a temporary or an output"},
    {"reading an output", "!!ARBfp1.0\nTEMP a;\nMOV a, result.color;\nEND\n", "result",
     "outputs cannot be read"},
    {"text after END", "!!ARBfp1.0\nMOV result.color, fragment.color;\nEND junk\n", "junk",
     "expected nothing after END"},
    {"no END", "!!ARBfp1.0\nMOV result.color, fragment.color;\n", "", "found the end"},
    {"lower-case opcode", "!!ARBfp1.0\nmov result.color, fragment.color;\nEND\n", "mov",
     "expected an instruction or a declaration"},
    {"texture coordinate past the limit",
     "!!ARBfp1.0\nMOV result.color, fragment.texcoord[8];\nEND\n", "8]", "below 8"},
    {"generic and named alias of one attribute",
     "!!ARBvp1.0\nMOV result.position, vertex.attrib[0];\nMOV result.color, vertex.position;\n"
     "END\n",
     "vertex.position;", "are the same attribute"},
    {"relative addressing in a fragment program",
     "!!ARBfp1.0\nPARAM c[2] = { program.local[0..1] };\nMOV result.color, c[A0.x];\nEND\n", "A0",
     "relative addressing is ARB_vertex_program's"},
    {"five-component vector", "!!ARBfp1.0\nPARAM k = {1, 2, 3, 4, 5};\nMOV result.color, k;\nEND\n",
     "5}", "four components at most"},
    {"ADDRESS in a fragment program", "!!ARBfp1.0\nADDRESS A0;\nEND\n", "ADDRESS",
     "ADDRESS is ARB_vertex_program's"},
    {"result.color[n] without ARB_draw_buffers",
     "!!ARBfp1.0\nMOV result.color[1], fragment.color;\nEND\n", "[1]", "ARB_draw_buffers"},
    {"a character of no token", "!!ARBfp1.0\nMOV result.color, fragment.color @;\nEND\n", "@",
     "not '@'"},
    {"a whole matrix as an operand", "!!ARBfp1.0\nMOV result.color, state.matrix.mvp;\nEND\n",
     ";\nEND", "expected .row[n]"},
    {"ARL into a temporary", "!!ARBvp1.0\nTEMP t;\nARL t.x, vertex.position.x;\nEND\n", "t.x",
     "an ADDRESS register"},
    {"ARB_vertex_blend's weight", "!!ARBvp1.0\nMOV result.position, vertex.weight;\nEND\n",
     "weight", "ARB_vertex_blend"},
};

}  // namespace lt::test
