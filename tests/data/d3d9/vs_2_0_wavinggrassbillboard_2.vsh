vs_2_0
; 103 ALU
def c30, 0.00000000, 1.00000000, 6.40884876, -3.14159274
def c31, 0.00600000, 0.02000000, 0.05000000, -0.16161616
def c32, 0.01200000, 0.02000000, 0.06000000, 0.02400000
def c33, 1.20000005, 2.00000000, 1.60000002, 4.80000019
def c34, 0.00833330, -0.00019841, -0.50000000, 0.50000000
def c35, 0.00600000, 0.02000000, -0.02000000, 0.10000000
def c36, 0.02400000, 0.04000000, -0.12000000, 0.09600000
def c37, 0.47193992, 0.18877596, 0.09438798, 0
dcl_position0 v0
dcl_tangent0 v1
dcl_normal0 v2
dcl_texcoord0 v3
dcl_color0 v5
add r0.xyz, v0, -c27
dp3 r0.x, r0, r0
slt r0.x, c26.w, r0
max r0.x, -r0, r0
slt r0.x, c30, r0
add r0.x, -r0, c30.y
mul r0.xy, r0.x, v1
mad r1.xyz, r0.x, c28, v0
mad r0.xyz, r0.y, c29, r1
mul r0.w, r0.z, c26.y
mul r1.xyz, r0.w, c31
mul r0.w, r0.x, c26.y
mad r1, r0.w, c32, r1.xyyz
mov r0.w, c26.x
mad r1, c33, r0.w, r1
frc r1, r1
mad r1, r1, c30.z, c30.w
mul r2, r1, r1
mul r3, r2, r1
mad r1, r3, c31.w, r1
mul r3, r3, r2
mov r0.w, v0
mul r2, r3, r2
mad r1, r3, c34.x, r1
mad r1, r2, c34.y, r1
mul r1, r1, r1
mul r1, r1, r1
mul r2, r1, v1.y
dp4 r3.x, r2, c36
dp4 r3.y, r2, c35
mad r0.xz, -r3.xyyw, c26.z, r0
dp4 r2.z, r0, c2
dp4 r2.x, r0, c0
dp4 r2.y, r0, c1
mad r3.xyz, -r2, c18.w, c18
dp3 r2.w, r3, r3
rsq r3.w, r2.w
mul r4.xyz, r3.w, r3
dp3 r3.z, v2, c10
dp3 r3.y, v2, c9
dp3 r3.x, v2, c8
dp3 r3.w, r3, r4
mul r4.x, r2.w, c22.z
max r2.w, r3, c30.x
add r3.w, r4.x, c30.y
mad r4.xyz, -r2, c17.w, c17
rcp r3.w, r3.w
dp3 r4.w, r4, r4
mul r3.w, r2, r3
rsq r2.w, r4.w
mul r4.xyz, r2.w, r4
dp3 r2.w, r3, r4
mul r4.w, r4, c21.z
add r4.w, r4, c30.y
rcp r4.x, r4.w
max r2.w, r2, c30.x
mul r2.w, r2, r4.x
mad r4.xyz, -r2, c19.w, c19
mul r5.xyz, r2.w, c13
dp3 r2.w, r4, r4
rsq r4.w, r2.w
add r5.xyz, r5, c12
mad r5.xyz, r3.w, c14, r5
mul r3.w, r2, c23.z
mul r4.xyz, r4.w, r4
dp3 r2.w, r3, r4
add r3.w, r3, c30.y
max r2.w, r2, c30.x
rcp r3.w, r3.w
mul r3.w, r2, r3
mad r2.xyz, -r2, c20.w, c20
dp3 r2.w, r2, r2
mad r4.xyz, r3.w, c15, r5
rsq r3.w, r2.w
mul r2.xyz, r3.w, r2
dp3 r2.x, r3, r2
mul r2.w, r2, c24.z
add r2.w, r2, c30.y
rcp r2.y, r2.w
max r2.x, r2, c30
mul r2.w, r2.x, r2.y
mov r2.xyz, c25
add r2.xyz, c34.z, r2
dp4 r1.x, r1, c37.xxyz
mad r1.xyz, r1.x, r2, c34.w
add r2.xyz, r0, -c27
mad r3.xyz, r2.w, c16, r4
mul r1.xyz, r1, v5
mul r1.xyz, r1, r3
dp3 r1.w, r2, r2
mul oD0.xyz, r1, c33.y
add r1.x, -r1.w, c26.w
mul r1.x, r1, c27.w
mul r1.x, r1, c33.y
min r1.x, r1, c30.y
dp4 oPos.w, r0, c7
dp4 oPos.z, r0, c6
dp4 oPos.y, r0, c5
dp4 oPos.x, r0, c4
max oD0.w, r1.x, c30.x
mov oT0, v3
