#version 110
// CPU paths' G-buffer pass (src/paths/common/gbuffer.cpp), fragment stage: what each channel of
// the two or three RGBA32F targets carries is src/paths/common/gbuffer_layout.h's to say, and
// the #defines are its choice for the scene. Every value is the varying as interpolated, moved
// to a channel, never computed on.
{{DEFINES}}
uniform float u_material_plus_one;
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
  gl_FragData[0] = vec4(v_position, u_material_plus_one);
#if LT_MAP_UV
  gl_FragData[1] = vec4(v_normal, v_uv.x);
#elif LT_GREY_THICKNESS
  gl_FragData[1] = vec4(v_normal, v_grey_thickness);
#else
  gl_FragData[1] = vec4(v_normal, 0.0);
#endif
#if LT_RGB_THICKNESS && LT_MAP_UV
  gl_FragData[2] = vec4(v_thickness, v_uv.y);
#elif LT_RGB_THICKNESS
  gl_FragData[2] = vec4(v_thickness, 0.0);
#elif LT_MAP_UV
  gl_FragData[2] = vec4(0.0, 0.0, 0.0, v_uv.y);
#endif
}
