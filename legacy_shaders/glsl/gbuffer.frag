#version 110
// reference path, G-buffer pass: three RGBA32F targets, and a fourth when a material samples a
// map (gl_FragData[3] is discarded when only three draw buffers are bound).
//   0: camera-relative position, coverage (1)
//   1: interpolated normal (NOT renormalised: the CPU does that in double), material index
//   2: interpolated vertex thickness colour
//   3: interpolated (u, v) for a thickness or albedo map
uniform float u_material;
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_thickness;
varying vec2 v_uv;

void main() {
  gl_FragData[0] = vec4(v_position, 1.0);
  gl_FragData[1] = vec4(v_normal, u_material);
  gl_FragData[2] = vec4(v_thickness, 0.0);
  gl_FragData[3] = vec4(v_uv, 0.0, 0.0);
}
