vs_3_0
; 18 ALU
dcl_position o0
dcl_texcoord0 o1
dcl_texcoord1 o2
def c10, 0.50000000, -1.00000000, 1.00000000, 0.00000000
dcl_position0 v0
dcl_normal0 v1
dp4 r0.w, v0, c7
dp4 r0.x, v0, c4
dp4 r0.y, v0, c5
mul r1.xyz, r0.xyww, c10.x
mul r1.y, r1, c8.x
dp4 r2.z, v0, c2
dp4 r2.x, v0, c0
dp4 r2.y, v0, c1
mad r3.xyz, -r2, c10.yyzw, v1
mul r2.xyz, r2, c10.yyzw
slt r1.w, c10, v1.z
slt r0.z, v1, c10.w
add r0.z, r0, r1.w
mad o2.xyz, r0.z, r3, r2
dp4 r0.z, v0, c6
mad o1.xy, r1.z, c9.zwzw, r1
mov o0, r0
mov o1.zw, r0
