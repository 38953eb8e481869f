vs_2_0
; 17 ALU
def c5, 256.00000000, 512.00000000, 768.00000000, 1024.00000000
def c6, 1.00000000, 0, 0, 0
dcl_position0 v0
dcl_color0 v1
dcl_texcoord0 v2
dcl_texcoord1 v3
sge r0.x, c5, v3
sge r0.y, c5, v3.x
add r0.w, -r0.x, c6.x
add r1.x, -r0.y, c6
sge r0.z, c5, v3.x
mul oT1.x, r0.z, r1
mul oT1.y, r0, r0.w
add r0.z, -r0, c6.x
sge r0.y, c5.w, v3.x
mov oD0, v1
mad oT0.xy, v2, c4, c4.zwzw
mul oT1.z, r0.y, r0
dp4 oPos.w, v0, c3
dp4 oPos.z, v0, c2
dp4 oPos.y, v0, c1
dp4 oPos.x, v0, c0
mov oT1.w, r0.x
