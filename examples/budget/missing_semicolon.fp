!!ARBfp1.0
# Invalid on purpose: the first MOV has no semicolon.
TEMP a;
MOV a, fragment.color
MOV result.color, a;
END
