!!ARBfp1.0
# A tinted texture: one TEX, one MUL.
OPTION ARB_precision_hint_fastest;
TEMP a;
TEX a, fragment.texcoord[0], texture[0], 2D;
MUL result.color, a, {0.5, 0.5, 0.5, 1};
END
