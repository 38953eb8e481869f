    vs_1_1
    dcl_position v0
    dcl_normal v1
    dcl_color v2
    dcl_texcoord v3
    dcl_texcoord1 v4
    dcl_texcoord2 v5
    dcl_texcoord3 v6
    def c14, 1, 0, 1, 0
    m4x4 r0, v0, c0
    mov oPos, r0
    dp4 r0.x, v0, c15
    mad r0.z, -r0.x, c7.y, c7.x
    dp3 r1.x, -c4, v1
    sge r1.x, r1.x, c14.y
    mul r7.w, r0.z, r1.x
    mov oFog, c14.x
    m4x4 r0, v0, c8
    dp4 r1.x, r0, c12
    dp4 r1.y, r0, c13
    mov oT0.xy, r1.xyyy
    mov oD0.xyz, r7.w
    mov oD0.w, c14.x

// approximately 20 instruction slots used
