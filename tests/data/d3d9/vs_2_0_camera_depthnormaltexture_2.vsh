vs_2_0
; 58 ALU
def c18, 0.00000000, 1.00000000, 6.40884876, -3.14159274
def c19, 0.00600000, 0.02000000, 0.05000000, -0.16161616
def c20, 0.01200000, 0.02000000, 0.06000000, 0.02400000
def c21, 1.20000005, 2.00000000, 1.60000002, 4.80000019
def c22, 0.00833330, -0.00019841, -0.50000000, 0.50000000
def c23, 0.00600000, 0.02000000, -0.02000000, 0.10000000
def c24, 0.02400000, 0.04000000, -0.12000000, 0.09600000
def c25, 0.47193992, 0.18877596, 0.09438798, 0
dcl_position0 v0
dcl_tangent0 v1
dcl_normal0 v2
dcl_texcoord0 v3
dcl_color0 v5
add r0.xyz, v0, -c15
dp3 r0.x, r0, r0
slt r0.x, c14.w, r0
max r0.x, -r0, r0
slt r0.x, c18, r0
add r0.x, -r0, c18.y
mul r0.xy, r0.x, v1
mad r1.xyz, r0.x, c16, v0
mad r3.xyz, r0.y, c17, r1
mul r0.x, r3.z, c14.y
mul r1.xyz, r0.x, c19
mul r0.x, r3, c14.y
mad r0, r0.x, c20, r1.xyyz
mov r1.x, c14
mad r0, c21, r1.x, r0
frc r0, r0
mad r0, r0, c18.z, c18.w
mul r1, r0, r0
mul r2, r1, r0
mad r0, r2, c19.w, r0
mul r2, r2, r1
mul r1, r2, r1
mad r0, r2, c22.x, r0
mad r0, r1, c22.y, r0
mul r0, r0, r0
mul r0, r0, r0
mul r1, r0, v1.y
dp4 r2.y, r1, c23
dp4 r2.x, r1, c24
mad r1.xz, -r2.xyyw, c14.z, r3
mov r1.y, r3
mov r1.w, v0
add r2.xyz, r1, -c15
dp3 r2.x, r2, r2
add r2.x, -r2, c14.w
mul r2.x, r2, c15.w
mul r2.x, r2, c21.y
min r2.x, r2, c18.y
max oD0.w, r2.x, c18.x
dp4 oPos.w, r1, c7
dp4 oPos.z, r1, c6
dp4 oPos.y, r1, c5
dp4 oPos.x, r1, c4
dp4 r1.w, r1, c2
dp4 r0.x, r0, c25.xxyz
mov r2.xyz, c13
add r1.xyz, c22.z, r2
mad r0.xyz, r0.x, r1, c22.w
mul r0.w, r1, c12
mul r0.xyz, r0, v5
mov oT1.w, -r0
mul oD0.xyz, r0, c21.y
mov oT0.xy, v3
dp3 oT1.z, v2, c10
dp3 oT1.y, v2, c9
dp3 oT1.x, v2, c8
