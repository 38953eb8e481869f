!!ARBfp1.0
OPTION ARB_precision_hint_fastest;
# 12 ALU, 2 TEX
PARAM c[4] = { program.local[0..2],
		{ 0, 2 } };
TEMP R0;
TEMP R1;
TEMP R2;
TEX R0, fragment.texcoord[0], texture[0], 2D;
TEX R1.w, fragment.texcoord[0].zwzw, texture[1], 2D;
MUL R0, R0, c[2];
MUL R2.xyz, R0, R1.w;
MUL R1.xyz, R0, fragment.texcoord[2];
DP3 R1.w, fragment.texcoord[1], c[0];
MUL R0.xyz, R0, c[1];
MAX R1.w, R1, c[3].x;
MUL R0.xyz, R1.w, R0;
MAD R0.xyz, R0, c[3].y, R1;
ADD result.color.xyz, R0, R2;
MOV result.color.w, R0;
END
# 12 instructions, 3 R-regs
