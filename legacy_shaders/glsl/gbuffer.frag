#version 110
// CPU paths' G-buffer pass (src/paths/common/gbuffer.cpp), fragment stage. Each RGBA32F target
// costs llvmpipe about as much as a varying's interpolation and its read-back, so the values are
// packed into two targets, and a third only when a material reads it (issue 39):
//   0: camera-relative position; material index + 1 (the target is cleared to 0: 0 = uncovered)
//   1: interpolated normal (NOT renormalised: the CPU does that in double); map u
//   2: interpolated vertex thickness colour; map v (bound only when LT_THIRD_TARGET)
// A channel nothing reads is written 0 and its varying is not interpolated at all.
{{DEFINES}}
#define LT_THIRD_TARGET (LT_VERTEX_THICKNESS || LT_MAP_UV)
uniform float u_material_plus_one;
varying vec3 v_position;
varying vec3 v_normal;
#if LT_VERTEX_THICKNESS
varying vec3 v_thickness;
#endif
#if LT_MAP_UV
varying vec2 v_uv;
#endif

void main() {
#if LT_MAP_UV
  vec2 uv = v_uv;
#else
  vec2 uv = vec2(0.0);
#endif
  gl_FragData[0] = vec4(v_position, u_material_plus_one);
  gl_FragData[1] = vec4(v_normal, uv.x);
#if LT_THIRD_TARGET
#if LT_VERTEX_THICKNESS
  gl_FragData[2] = vec4(v_thickness, uv.y);
#else
  gl_FragData[2] = vec4(0.0, 0.0, 0.0, uv.y);
#endif
#endif
}
