!!ARBfp1.0
OPTION ARB_precision_hint_fastest;
# 6 ALU, 2 TEX
PARAM c[2] = { program.local[0],
		{ 0.2199707, 0.70703125, 0.070983887, 0.5 } };
TEMP R0;
TEX R0, fragment.texcoord[0], texture[0], 2D;
DP3 R0.x, R0, c[1];
MOV R0.y, c[1].w;
ADD R0.x, R0, c[0];
MOV result.color.w, R0;
TEX result.color.xyz, R0, texture[1], 2D;
END
# 6 instructions, 1 R-regs
