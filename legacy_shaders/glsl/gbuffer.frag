#version 110
// reference path, G-buffer pass: three RGBA32F targets.
//   0: camera-relative position, coverage (1)
//   1: interpolated normal (NOT renormalised: the CPU does that in double), material index
//   2: interpolated vertex thickness colour, or a thickness map material's (u, v, 0)
uniform float u_material;
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_thickness;

void main() {
  gl_FragData[0] = vec4(v_position, 1.0);
  gl_FragData[1] = vec4(v_normal, u_material);
  gl_FragData[2] = vec4(v_thickness, 0.0);
}
