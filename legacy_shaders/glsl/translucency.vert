#version 110
// glsl path, vertex stage: passes the camera-relative position, the world normal and (only when
// the material reads vertex thickness) the vertex colour. All shading is per pixel.
// ftransform() keeps rasterisation bit-identical to the G-buffer pass and the fixed-function paths.
{{DEFINES}}
varying vec3 v_position;
varying vec3 v_normal;
#if LT_VERTEX_THICKNESS
varying vec3 v_thickness;
#endif

void main() {
  v_position = gl_Vertex.xyz;
  v_normal = gl_Normal;
#if LT_VERTEX_THICKNESS
  v_thickness = gl_Color.rgb;
#endif
  gl_Position = ftransform();
}
