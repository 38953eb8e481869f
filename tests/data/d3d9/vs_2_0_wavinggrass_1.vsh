vs_2_0
; 56 ALU
def c18, 0.00600000, 0.02000000, 0.05000000, -0.16161616
def c19, 0.01200000, 0.02000000, 0.06000000, 0.02400000
def c20, 1.20000005, 2.00000000, 1.60000002, 4.80000019
def c21, 6.40884876, -3.14159274, 0.00833330, -0.00019841
def c22, 0.00600000, 0.02000000, -0.02000000, 0.10000000
def c23, 0.02400000, 0.04000000, -0.12000000, 0.09600000
def c24, 0.47193992, 0.18877596, 0.09438798, -0.50000000
def c25, 0.50000000, 1.00000000, 0.00000000, 0
dcl_position0 v0
dcl_normal0 v2
dcl_texcoord0 v3
dcl_color0 v5
mul r0.x, v0.z, c15.y
mul r1.xyz, r0.x, c18
mul r0.x, v0, c15.y
mad r1, r0.x, c19, r1.xyyz
mov r0.x, c15
mad r0, c20, r0.x, r1
frc r0, r0
mad r0, r0, c21.x, c21.y
mul r1, r0, r0
mul r2, r1, r0
mad r0, r2, c18.w, r0
mul r2, r2, r1
mul r1, r2, r1
mad r0, r2, c21.z, r0
mad r0, r1, c21.w, r0
mul r0, r0, r0
mov r1.yw, v0
mul r2, r0, r0
mul r1.x, v5.w, c15.z
mul r0, r2, r1.x
dp4 r1.z, r0, c22
dp4 r1.x, r0, c23
mad r1.xz, -r1, c15.z, v0
dp4 r0.z, r1, c6
dp4 r0.x, r1, c4
dp4 r0.y, r1, c5
dp4 r0.w, r1, c7
dp4 oT3.w, r0, c11
dp4 oT3.z, r0, c10
dp4 oT3.y, r0, c9
dp4 oT3.x, r0, c8
add oT2.xyz, -r0, c13
add r0.xyz, r1, -c16
dp3 r0.x, r0, r0
add r0.x, -r0, c15.w
mul r0.x, r0, c16.w
mul r0.w, r0.x, c20.y
mov r0.xyz, c14
min r0.w, r0, c25.y
dp4 oPos.w, r1, c3
dp4 oPos.z, r1, c2
dp4 oPos.y, r1, c1
dp4 oPos.x, r1, c0
dp4 r1.x, r2, c24.xxyz
add r0.xyz, c24.w, r0
mad r0.xyz, r1.x, r0, c25.x
mul r1.xyz, v2, c12.w
mul r0.xyz, v5, r0
max oD0.w, r0, c25.z
mul oD0.xyz, r0, c20.y
dp3 oT1.z, r1, c6
dp3 oT1.y, r1, c5
dp3 oT1.x, r1, c4
mad oT0.xy, v3, c17, c17.zwzw
