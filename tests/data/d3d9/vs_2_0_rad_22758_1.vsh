vs_2_0
; 16 ALU
def c16, 1.00000000, 0.50000000, 0, 0
dcl_position0 v0
dcl_normal0 v2
dcl_texcoord1 v4
mov r0.xyz, v2
mov r0.w, c16.x
mad r1, r0, c14.x, v0
dp4 r0.w, r1, c3
dp4 r0.z, r1, c2
dp4 r0.x, r1, c0
dp4 r0.y, r1, c1
mul r2.xyz, r0.xyww, c16.y
mul r2.y, r2, c12.x
mad oT0.xy, r2.z, c13.zwzw, r2
mov oPos, r0
mov oT0.zw, r0
dp4 oT1.z, r1, c6
dp4 oT1.y, r1, c5
dp4 oT1.x, r1, c4
mad oT2.xy, v4, c15, c15.zwzw
