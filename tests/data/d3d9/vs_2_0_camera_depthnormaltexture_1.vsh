vs_2_0
; 62 ALU
def c22, 0.00000000, 1.00000000, 2.00000000, -0.50000000
def c23, 1.97500002, 0.79299998, 0.37500000, 0.19300000
def c24, 2.00000000, -1.00000000, 3.00000000, 0.30000001
def c25, 0.10000000, 0, 0, 0
dcl_position0 v0
dcl_tangent0 v1
dcl_normal0 v2
dcl_texcoord0 v3
dcl_texcoord1 v4
dcl_color0 v5
mul r0, v2.y, c9
mad r1, v2.x, c8, r0
add r0.xyz, r1, c22.x
abs r0.w, v1
add r3.w, -r0, c22.y
mad r0.xyz, r0, r3.w, v0
mov r2.xyz, c15
dp3 r0.w, c22.y, r2
mad r1, v2.z, c10, r1
add r2, r1, c22.x
dp4 r2.w, r2, r2
mul r3.xyz, r0, c18
add r0.w, v5.x, r0
add r0.x, v5.y, r0.w
mov r0.y, r0.w
dp3 r0.x, r3, r0.x
add r0.xy, r0, c16.y
mul r0, r0.xxyy, c23
frc r0, r0
mad r0, r0, c22.z, c22.w
frc r0, r0
mad r0, r0, c24.x, c24.y
abs r0, r0
mul r1, r0, r0
mad r0, -r0, c24.x, c24.z
mul r0, r1, r0
add r4.xy, r0.xzzw, r0.ywzw
rsq r2.w, r2.w
mad r1.xyz, r2.w, r2, -v2
mad r1.xyz, r3.w, r1, v2
mul r0.xyz, r4.y, c21
mul r2.xyz, v4.y, r0
mul r4.zw, v5.y, r1.xyxz
mov r0.w, c22.y
dp3 r1.w, r1, r1
mul r0.xz, r4.zyww, c25.x
mul r0.y, v4, c24.w
mad r0.xyz, r4.xyxw, r0, r2
mad r0.xyz, r0, c21.w, r3
mad r2.xyz, v4.x, c21, r0
dp3 r0.x, r2, c19
add r0.x, r0, c19.w
mul r0.xyz, r0.x, c19
add r2.xyz, -r0, r2
mad r0.xyz, r0, c20.x, r2
dp4 oPos.w, r0, c7
dp4 oPos.z, r0, c6
dp4 oPos.y, r0, c5
dp4 oPos.x, r0, c4
dp4 r0.x, r0, c2
rsq r0.y, r1.w
mul r1.xyz, r0.y, r1
mul r0.x, r0, c17.w
mov oT1.w, -r0.x
dp3 oT1.z, r1, c10
dp3 oT1.y, r1, c9
dp3 oT1.x, r1, c8
mov oT0.xy, v3
