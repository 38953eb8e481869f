#version 110
// CPU paths' G-buffer pass, vertex stage: rasterises what the CPU shades. Same transform
// (ftransform) as every other path, so coverage is identical. The #defines
// (src/paths/common/gbuffer_layout.h) leave out the varyings no material reads.
{{DEFINES}}
varying vec3 v_position;
varying vec3 v_normal;
#if LT_RGB_THICKNESS
varying vec3 v_thickness;
#endif
#if LT_GREY_THICKNESS
varying float v_grey_thickness;
#endif
#if LT_MAP_UV
varying vec2 v_uv;
#endif

void main() {
  v_position = gl_Vertex.xyz;
  v_normal = gl_Normal;
  // The vertex colour, or (1,1,1) when the mesh has none (gl/scene_geometry.h sets it); grey
  // when every colour has red = green = blue, and then red alone is interpolated.
#if LT_RGB_THICKNESS
  v_thickness = gl_Color.rgb;
#endif
#if LT_GREY_THICKNESS
  v_grey_thickness = gl_Color.r;
#endif
#if LT_MAP_UV
  // The mesh's UVs (texture coordinate set 1, gl/scene_geometry.h): bound only for a material
  // that samples a map.
  v_uv = gl_MultiTexCoord1.xy;
#endif
  gl_Position = ftransform();
}
