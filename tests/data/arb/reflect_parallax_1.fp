!!ARBfp1.0
OPTION ARB_precision_hint_fastest;
# 52 ALU, 7 TEX
PARAM c[7] = { program.local[0..2],
		{ 0.5, 0.41999999, 2, 1 },
		{ -0.40824828, -0.70710677, 0.57735026, 8 },
		{ -0.40824831, 0.70710677, 0.57735026 },
		{ 0.81649655, 0, 0.57735026 } };
TEMP R0;
TEMP R1;
TEMP R2;
TEMP R3;
TEMP R4;
DP3 R0.x, fragment.texcoord[1], fragment.texcoord[1];
RSQ R0.x, R0.x;
MUL R1.xyz, R0.x, fragment.texcoord[1];
ADD R0.x, R1.z, c[3].y;
RCP R0.y, R0.x;
MOV R0.x, c[2];
MUL R2.xy, R1, R0.y;
MUL R0.x, R0, c[3];
TEX R0.w, fragment.texcoord[0].zwzw, texture[0], 2D;
MAD R0.w, R0, c[2].x, -R0.x;
MAD R0.xy, R0.w, R2, fragment.texcoord[0].zwzw;
TEX R1.yw, R0, texture[2], 2D;
MAD R3.xy, R1.wyzw, c[3].z, -c[3].w;
MUL R0.x, R3.y, R3.y;
MAD R0.x, -R3, R3, -R0;
ADD R0.x, R0, c[3].w;
RSQ R0.x, R0.x;
RCP R3.z, R0.x;
DP3 R1.x, R3, fragment.texcoord[2];
DP3 R1.y, R3, fragment.texcoord[3];
DP3 R1.z, R3, fragment.texcoord[4];
DP3_SAT R4.z, R3, c[4];
DP3_SAT R4.y, R3, c[5];
DP3_SAT R4.x, R3, c[6];
MOV R0.x, fragment.texcoord[2].w;
MOV R0.z, fragment.texcoord[4].w;
MOV R0.y, fragment.texcoord[3].w;
DP3 R1.w, R1, R0;
MUL R1.xyz, R1, R1.w;
MAD R0.xyz, -R1, c[3].z, R0;
MAD R1.xy, R0.w, R2, fragment.texcoord[0];
TEX R2, R1, texture[1], 2D;
TEX R0, R0, texture[3], CUBE;
MUL R1, R2.w, R0;
MUL R1, R1, c[1];
TEX R0, fragment.texcoord[5], texture[6], 2D;
MUL R0.xyz, R0.w, R0;
MUL R0.xyz, R0, R4;
DP3 R0.y, R0, c[4].w;
TEX R3, fragment.texcoord[5], texture[5], 2D;
MUL R4.xyz, R3.w, R3;
MUL R4.xyz, R4, R0.y;
TXP R0.x, fragment.texcoord[6], texture[4], 2D;
MUL R3.xyz, R3, R0.x;
MUL R4.xyz, R4, c[4].w;
MUL R3.xyz, R3, c[3].z;
MUL R0.xyz, R4, R0.x;
MIN R3.xyz, R4, R3;
MAX R0.xyz, R3, R0;
MUL R2.xyz, R2, c[0];
MAD result.color.xyz, R2, R0, R1;
MOV result.color.w, R1;
END
# 52 instructions, 5 R-regs
