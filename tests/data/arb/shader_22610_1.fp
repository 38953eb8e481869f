!!ARBfp1.0
OPTION ARB_precision_hint_fastest;
# 23 ALU, 5 TEX
PARAM c[3] = { program.local[0..1],
		{ 8 } };
TEMP R0;
TEMP R1;
TEMP R2;
TEMP R3;
TEMP R4;
TEX R2, fragment.texcoord[2], texture[4], 2D;
TEX R3, fragment.texcoord[2], texture[3], 2D;
TEX R0, fragment.texcoord[0], texture[0], 2D;
TEX R1, fragment.texcoord[0].zwzw, texture[1], 2D;
TXP R4.xyz, fragment.texcoord[1], texture[2], 2D;
MUL R3.xyz, R3.w, R3;
MUL R2.xyz, R2.w, R2;
MUL R2.xyz, R2, c[2].x;
DP4 R3.w, fragment.texcoord[3], fragment.texcoord[3];
RSQ R2.w, R3.w;
RCP R2.w, R2.w;
ADD R1.xyz, R1, -R0;
MAD R0.xyz, R1.w, R1, R0;
MUL R0, R0, c[0];
MAD R3.xyz, R3, c[2].x, -R2;
MAD_SAT R2.w, R2, c[1].z, c[1];
MAD R2.xyz, R2.w, R3, R2;
LG2 R3.x, R4.x;
LG2 R3.y, R4.y;
LG2 R3.z, R4.z;
ADD R2.xyz, -R3, R2;
MUL result.color.xyz, R0, R2;
MOV result.color.w, R0;
END
# 23 instructions, 5 R-regs
