vs_2_0
; 53 ALU
def c15, 0.00000000, 1.00000000, 6.40884876, -3.14159274
def c16, 0.00600000, 0.02000000, 0.05000000, -0.16161616
def c17, 0.01200000, 0.02000000, 0.06000000, 0.02400000
def c18, 1.20000005, 2.00000000, 1.60000002, 4.80000019
def c19, 0.00833330, -0.00019841, -0.50000000, 0.50000000
def c20, 0.00600000, 0.02000000, -0.02000000, 0.10000000
def c21, 0.02400000, 0.04000000, -0.12000000, 0.09600000
def c22, 0.47193992, 0.18877596, 0.09438798, 0
dcl_position0 v0
dcl_tangent0 v1
dcl_texcoord0 v3
dcl_texcoord1 v4
dcl_color0 v5
add r0.xyz, v0, -c10
dp3 r0.x, r0, r0
slt r0.x, c9.w, r0
max r0.x, -r0, r0
slt r0.x, c15, r0
add r0.x, -r0, c15.y
mul r0.xy, r0.x, v1
mad r1.xyz, r0.x, c11, v0
mad r3.xyz, r0.y, c12, r1
mul r0.x, r3.z, c9.y
mul r1.xyz, r0.x, c16
mul r0.x, r3, c9.y
mad r0, r0.x, c17, r1.xyyz
mov r1.x, c9
mad r0, c18, r1.x, r0
frc r0, r0
mad r0, r0, c15.z, c15.w
mul r1, r0, r0
mul r2, r1, r0
mad r0, r2, c16.w, r0
mul r2, r2, r1
mul r1, r2, r1
mad r0, r2, c19.x, r0
mad r0, r1, c19.y, r0
mul r0, r0, r0
mul r0, r0, r0
mul r1, r0, v1.y
dp4 r2.x, r1, c21
dp4 r2.y, r1, c20
mad r1.xz, -r2.xyyw, c9.z, r3
mov r1.y, r3
mov r1.w, v0
add r2.xyz, r1, -c10
dp3 r2.x, r2, r2
dp4 oPos.w, r1, c3
dp4 oPos.z, r1, c2
dp4 oPos.y, r1, c1
dp4 oPos.x, r1, c0
add r2.x, -r2, c9.w
mul r1.w, r2.x, c10
mov r1.xyz, c8
dp4 r0.x, r0, c22.xxyz
mul r1.w, r1, c18.y
add r1.xyz, c19.z, r1
mad r0.xyz, r0.x, r1, c19.w
min r0.w, r1, c15.y
mul r0.xyz, r0, v5
max oD0.w, r0, c15.x
mul oD0.xyz, r0, c18.y
mad oT0.xy, v3, c14, c14.zwzw
mad oT1.xy, v4, c13, c13.zwzw
