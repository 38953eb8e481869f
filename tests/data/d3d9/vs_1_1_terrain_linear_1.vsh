    vs_1_1
    dcl_position v0
    dcl_normal v1
    dcl_color v2
    dcl_texcoord v3
    dcl_texcoord1 v4
    dcl_texcoord2 v5
    dcl_texcoord3 v6
    dcl_texcoord4 v7
    dcl_texcoord5 v8
    def c14, 1, 0, 0.5, 0
    m4x4 oPos, v0, c0
    dp4 r0.x, v0, c15
    mad oFog, -r0.x, c7.y, c7.x
    mov oT0.xy, v3
    mov oT1.xy, v4
    mov oT2.xy, v5
    mov oT3.xy, v6
    mov oT4.xy, v7
    mov oT5.xy, v8
    dp3 r1.x, c4, v1
    max r1.x, c14.y, -r1.x
    mul r3, c5, r1.x
    mad oD0, r3, v2, c6

// approximately 16 instruction slots used
