vs_2_0
; 94 ALU
def c23, -0.02083333, -0.12500000, 1.00000000, 0.50000000
def c24, -0.00000155, -0.00002170, 0.00260417, 0.00026042
def c25, 0.15915491, 0.50000000, 6.28318501, -3.14159298
dcl_position0 v0
dcl_tangent0 v1
dcl_normal0 v2
dcl_texcoord0 v3
mov r0.x, c16.w
mul r2, c21, r0.x
mad r0.x, r2, c25, c25.y
mad r0.y, r2, c25.x, c25
frc r0.x, r0
mad r0.x, r0, c25.z, c25.w
sincos r1.xy, r0.x, c24.xyzw, c23.xyzw
frc r0.y, r0
mad r1.x, r0.y, c25.z, c25.w
sincos r0.xy, r1.x, c24.xyzw, c23.xyzw
mov r0.x, r1.y
mad r0.w, r2, c25.x, c25.y
mad r0.z, r2, c25.x, c25.y
frc r0.w, r0
mad r0.w, r0, c25.z, c25
sincos r2.xy, r0.w, c24.xyzw, c23.xyzw
mov r0.w, r2.y
mov r2.xyz, v1
mul r3.xyz, v2.zxyw, r2.yzxw
mov r2.xyz, v1
mad r3.xyz, v2.yzxw, r2.zxyw, -r3
mov r2, c8
dp4 r4.x, c19, r2
frc r0.z, r0
mad r0.z, r0, c25, c25.w
sincos r1.xy, r0.z, c24.xyzw, c23.xyzw
mov r0.z, r1.y
mad r0, r0, c20, v0
dp4 r1.w, r0, c7
dp4 r1.z, r0, c6
dp4 r1.x, r0, c4
dp4 r1.y, r0, c5
mov r2.xyz, c18
mov r2.w, c23.z
mul r3.xyz, r3, v1.w
dp4 oT3.z, r1, c14
dp4 oT3.y, r1, c13
dp4 oT3.x, r1, c12
mov r1, c10
dp4 r4.z, c19, r1
mov r1, c9
dp4 r4.y, c19, r1
mad r1.xyz, r4, c17.w, -r0
dp4 r4.z, r2, c10
dp4 r4.x, r2, c8
dp4 r4.y, r2, c9
mad r2.xyz, r4, c17.w, -r0
dp3 oT1.z, v2, r1
dp3 oT1.y, r1, r3
dp3 oT1.x, r1, v1
dp3 oT2.z, v2, r2
dp3 oT2.y, r3, r2
dp3 oT2.x, v1, r2
dp4 oPos.w, r0, c3
dp4 oPos.z, r0, c2
dp4 oPos.y, r0, c1
dp4 oPos.x, r0, c0
mad oT0.xy, v3, c22, c22.zwzw
