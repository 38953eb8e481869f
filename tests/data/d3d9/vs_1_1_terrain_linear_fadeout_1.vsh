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
    mul r0, v0.y, c18
    mad r0, c17, v0.x, r0
    mad r0, c19, v0.z, r0
    mad r1, c20, v0.w, r0
    dp4 r1.w, r1, r1
    rsq r2.w, r1.w
    mul r1.w, r2.w, r1.w
    mad r1.w, r1.w, c16.x, -c16.y
    add oD0.w, -r1.w, c14.x

// approximately 25 instruction slots used
