#version 110
// reference path, G-buffer pass: rasterises what the CPU shades in double. Same transform
// (ftransform) as every other path, so coverage is identical.
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_thickness;
varying vec2 v_uv;

void main() {
  v_position = gl_Vertex.xyz;
  v_normal = gl_Normal;
  // The vertex colour, or (1,1,1) when the mesh has none (gl/scene_geometry.h sets it).
  v_thickness = gl_Color.rgb;
  // The mesh's UVs (texture coordinate set 1, gl/scene_geometry.h): bound only for a material
  // that samples a map; (0, 0) otherwise, and then unread.
  v_uv = gl_MultiTexCoord1.xy;
  gl_Position = ftransform();
}
