#version 130
// gx path, rasteriser: RGBA32F targets for the CPU's TEV.
//   0, 1: the two channel colours, 0..255 per component, interpolated (not yet truncated)
//   2:    the material index and coverage (1)
//   3..:  one texture coordinate (s, t, q) per texgen
uniform float u_material;
noperspective in vec4 v_color0;
noperspective in vec4 v_color1;
{{TEXCOORD_INPUTS}}

void main() {
  gl_FragData[0] = v_color0;
  gl_FragData[1] = v_color1;
  gl_FragData[2] = vec4(u_material, 1.0, 0.0, 0.0);
{{TEXCOORD_WRITES}}
}
