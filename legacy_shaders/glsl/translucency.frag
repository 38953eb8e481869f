#version 110
// glsl path, fragment stage: the equation of model.md per pixel, in float, with exact pow.
// Generated per material by src/paths/glsl/glsl_path.cpp: the #defines select what the scene
// uses and the generator writes one call per light into main(), so nothing unused is compiled in.
{{DEFINES}}
uniform vec3 u_albedo;
#if LT_AMBIENT_LIGHT
uniform vec3 u_ambient_light;
#endif
#if LT_ORTHOGRAPHIC
uniform vec3 u_view_dir;  // -forward: every view ray is parallel
#endif
#if LT_TRANSLUCENCY
uniform float u_power;
uniform float u_distortion;
uniform float u_lt_ambient;
uniform vec3 u_thickness;  // constant thickness * tint, or the tint alone (vertex, map)
#endif
#if LT_THICKNESS_MAP
uniform sampler2D u_thickness_map;  // GL_LINEAR, CLAMP_TO_EDGE (gl/map_texture.h)
#endif
#if LT_ALBEDO_MAP
uniform sampler2D u_albedo_map;  // linear rgb (sRGB decoded on load), its sampler's wrap
#endif
#if LT_RAMP
uniform sampler2D u_ramp;  // the artist's W x 1 ramp: its value at t replaces pow(t, p)
#endif
{{LIGHT_UNIFORMS}}
varying vec3 v_position;
varying vec3 v_normal;
#if LT_VERTEX_THICKNESS
varying vec3 v_thickness;
#endif
#if LT_THICKNESS_MAP || LT_ALBEDO_MAP
varying vec2 v_uv;
#endif

// model.md hard case: a normal that interpolates to ~0 is "no normal" (same 1e-6 as the reference).
vec3 normal_or_zero(vec3 n) {
  float len = length(n);
  return len >= 1e-6 ? n / len : vec3(0.0);
}

#if LT_POINT_LIGHTS
// A light exactly at the point lights it head-on (L = N); the denominator floor keeps att finite.
void point_light(vec3 P, vec3 N, vec3 position, vec3 k, out vec3 L, out float att) {
  vec3 d = position - P;
  float dist = length(d);
  L = dist > 0.0 ? d / dist : N;
  att = 1.0 / max(k.x + k.y * dist + k.z * dist * dist, 1e-6);
}
#endif

#if LT_TRANSLUCENCY && !LT_RAMP
float lobe(float t) {
#if LT_POWER_ZERO
  return 1.0;  // 0^0 := 1: the material's lobe is flat
#else
  // GLSL leaves pow(0, p) undefined (it is exp2(p * log2(0))): 0 is the model's value.
  return t > 0.0 ? pow(t, u_power) : 0.0;
#endif
}
#endif

vec3 light_term(vec3 N, vec3 V, vec3 L, float att, vec3 color, float scale, vec3 T) {
  vec3 result = vec3(max(dot(N, L), 0.0));
#if LT_TRANSLUCENCY
  vec3 H = L + N * u_distortion;  // not normalised: the seed's choice (the dot is saturated)
#if LT_NORMALIZE_H
  float h = length(H);
  H = h > 0.0 ? H / h : vec3(0.0);
#endif
  float t = clamp(dot(V, -H), 0.0, 1.0);
#if LT_RAMP
  result += (texture2D(u_ramp, vec2(t, 0.5)).rgb * scale + u_lt_ambient) * T;
#else
  result += (lobe(t) * scale + u_lt_ambient) * T;
#endif
#endif
  return att * color * result;
}

void main() {
  vec3 N = normal_or_zero(v_normal);
#if LT_ORTHOGRAPHIC
  vec3 V = u_view_dir;
#else
  vec3 V = normalize(-v_position);  // the eye is the origin of camera-relative space
#endif
#if LT_TRANSLUCENCY
#if LT_VERTEX_THICKNESS
  vec3 T = v_thickness * u_thickness;
#elif LT_THICKNESS_MAP
  vec3 T = texture2D(u_thickness_map, v_uv).rgb * u_thickness;
#else
  vec3 T = u_thickness;
#endif
#else
  vec3 T = vec3(0.0);
#endif
  vec3 sum = vec3(0.0);
{{LIGHT_CALLS}}
#if LT_AMBIENT_LIGHT
  sum += u_ambient_light;
#endif
#if LT_ALBEDO_MAP
  // The seed's cDiffuseAlbedo from a texture: it multiplies diffuse and translucency alike.
  gl_FragColor = vec4(texture2D(u_albedo_map, v_uv).rgb * u_albedo * sum, 1.0);
#else
  gl_FragColor = vec4(u_albedo * sum, 1.0);
#endif
}
