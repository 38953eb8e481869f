!!ARBfp1.0
OPTION ARB_precision_hint_fastest;
# 16 ALU, 1 TEX
PARAM c[5] = { program.local[0..1],
		{ 0.99902344, 1, 0, 0.0024999999 },
		{ 1, 255, 65025, 1.6058138e+008 },
		{ 2, 0.0039215689 } };
TEMP R0;
TEX R0.x, fragment.texcoord[0], texture[0], 2D;
MAD R0.x, R0, c[0], c[0].y;
RCP R0.y, R0.x;
ADD R0.z, -R0.y, c[1].y;
SLT R0.y, c[1], R0;
ABS R0.w, R0.y;
ADD R0.z, R0, -c[2].w;
MUL R0.y, R0.z, c[4].x;
CMP R0.z, -R0.w, c[2], c[2].y;
CMP R0.y, -R0.z, R0, c[2].z;
RCP R0.x, c[1].w;
MUL R0.x, R0.y, R0;
MIN_SAT R0.x, R0, c[2];
MUL R0, R0.x, c[3];
FRC R0, R0;
MAD result.color, -R0.yzww, c[4].y, R0;
END
# 16 instructions, 1 R-regs
