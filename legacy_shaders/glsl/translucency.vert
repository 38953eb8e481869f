#version 110
// glsl path, vertex stage: passes the camera-relative position, the world normal and (only when
// the material reads vertex thickness) the vertex colour, or (for a thickness or albedo map) the UVs. All shading is per pixel.
// ftransform() keeps rasterisation bit-identical to the G-buffer pass and the fixed-function paths.
{{DEFINES}}
varying vec3 v_position;
varying vec3 v_normal;
#if LT_VERTEX_THICKNESS
varying vec3 v_thickness;
#endif
#if LT_THICKNESS_MAP || LT_ALBEDO_MAP
varying vec2 v_uv;  // the mesh's UVs: texture coordinate set 1 (gl/scene_geometry.h)
#endif

void main() {
  v_position = gl_Vertex.xyz;
  v_normal = gl_Normal;
#if LT_VERTEX_THICKNESS
  v_thickness = gl_Color.rgb;
#endif
#if LT_THICKNESS_MAP || LT_ALBEDO_MAP
  v_uv = gl_MultiTexCoord1.xy;
#endif
  gl_Position = ftransform();
}
