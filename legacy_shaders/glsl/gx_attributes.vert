#version 130
// gx path, rasteriser: interpolates what the emulated XF computed per vertex, for the CPU's
// TEV. Same transform (ftransform) as every other path, so coverage is identical. Colours are
// interpolated linearly in screen space (noperspective), as Dolphin's software rasteriser does
// [DSW Rasterizer.cpp: colour slopes from the raw vertex colours, texture slopes over 1/w];
// texture coordinates perspective-correctly.
in vec4 a_color0;
in vec4 a_color1;
{{TEXCOORD_INPUTS}}
noperspective out vec4 v_color0;
noperspective out vec4 v_color1;
{{TEXCOORD_OUTPUTS}}

void main() {
  v_color0 = a_color0;
  v_color1 = a_color1;
{{TEXCOORD_ASSIGNS}}
  gl_Position = ftransform();
}
