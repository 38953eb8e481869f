#version 110
// reference path, G-buffer pass: rasterises what the CPU shades in double. Same transform
// (ftransform) as every other path, so coverage is identical.
uniform float u_uv_thickness;  // 1: the material samples a thickness map (the CPU does, at the UV)
varying vec3 v_position;
varying vec3 v_normal;
varying vec3 v_thickness;

void main() {
  v_position = gl_Vertex.xyz;
  v_normal = gl_Normal;
  // The vertex colour, or (1,1,1) when the mesh has none; a map material's (u, v, 0) instead
  // (texture coordinate set 1, gl/scene_geometry.h): its vertex colours play no part.
  v_thickness = u_uv_thickness > 0.5 ? vec3(gl_MultiTexCoord1.xy, 0.0) : gl_Color.rgb;
  gl_Position = ftransform();
}
