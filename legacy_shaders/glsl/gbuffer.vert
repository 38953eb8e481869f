#version 110
// reference path, G-buffer pass: rasterises what the CPU shades in double. Same transform
// (ftransform) as every other path, so coverage is identical.
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_thickness;

void main() {
  v_position = gl_Vertex.xyz;
  v_normal = gl_Normal;
  v_thickness = gl_Color.rgb;  // the vertex colour, or (1,1,1) when the mesh has none
  gl_Position = ftransform();
}
