// The equation of model.md evaluated the way an fp16 pixel shader evaluates it (the seed's
// `half3` code, PS3 RSX, mobile GPUs): every input rounded to IEEE binary16 and every intermediate
// rounded again. The scene's constants and the texture units are in Imath's half here; the
// shading itself, a run of pixels at a time in vector lanes, is half_shading_lanes.h.
#pragma once

#include <Imath/half.h>

#include <glm/glm.hpp>
#include <vector>

#include "model/texture_sampling.h"
#include "scene/scene.h"

namespace lt::fp16 {

using Imath::half;

// How the lobe t^p is evaluated, and whether the hard-case guards are on.
enum class PowMode {
  Exact,      // exp2(p * log2(t)) in half (what fp16 POW does), with the guards
  Sg,         // the spherical-Gaussian exp2(t * n' - n'), n' = 1.4427 p + 1.4427, with the guards
  Unguarded,  // exp2(p * log2(t)) with no guard at all: IEEE half, NaN and Inf included
};

// Largest finite half (65504) and smallest normal half (2^-14 = 6.1e-5).
inline constexpr float kHalfMax = 65504.0f;
inline constexpr float kHalfMinNormal = 6.103515625e-05f;

struct Vec3h {
  half x, y, z;
};

// A light as its fp16 shader would receive it: every constant already rounded to half.
struct LightH {
  bool point = false;
  Vec3h to_light;  // directional: -direction (already unit in the scene)
  Vec3h position;  // point: camera-relative
  Vec3h color;
  half scale;
  half kc, kl, kq;
};

// A texture as an fp16 texture unit holds it: half texels (the float texels rounded once, as a
// GL float->half upload does), row 0 = v = 0.
struct TextureH {
  int width = 0, height = 0;
  std::vector<Vec3h> texels;
  model::Wrap wrap_s = model::Wrap::ClampToEdge, wrap_t = model::Wrap::ClampToEdge;
};

// A material's constants in half. `thickness` is constant * tint, or the tint alone when the
// thickness comes from the vertex colour or a map (multiplied in per pixel, like the glsl path).
struct MaterialH {
  Vec3h albedo;
  bool albedo_mapped = false;  // `albedo_map` at the G-buffer's UV multiplies `albedo`
  TextureH albedo_map;         // its linear (sRGB-decoded) texels rounded to half
  bool translucent = false;
  bool vertex_thickness = false;
  bool map_thickness = false;  // `map` is sampled at the G-buffer's UV
  bool ramp_lobe = false;      // `ramp` at t replaces t^p, per channel
  TextureH map, ramp;
  bool normalize_h = false;
  half power, distortion, ambient;
  half sg_exponent;  // n' = 1.4427 p + 1.4427, itself computed in half
  Vec3h thickness;
};

// The whole scene's fp16 constants, built once per path from the camera-relative scene.
struct SceneH {
  Vec3h ambient_light;
  bool orthographic = false;
  Vec3h view_dir;  // -forward: orthographic V, and the fallback for a V that cannot be normalised
  std::vector<LightH> lights;
  std::vector<MaterialH> materials;
};

// `scene` must already hold camera-relative light positions (the G-buffer's space).
SceneH prepare_scene(const Scene& scene, PowMode mode);

// Bilinear (GL_LINEAR, CLAMP_TO_EDGE) as an fp16 pipeline does it: the coordinate is a float
// interpolant and the texel-space position, taps and fractions are the texture unit's addressing
// (model::bilinear_taps); each weight (fx, 1 - fx, fy, 1 - fy) is rounded to half, and the blend
// ((1-fy)((1-fx) t00 + fx t10) + fy((1-fx) t01 + fx t11)) rounds every product and sum to half,
// saturating at +-65504 when `guarded` (the shader's mode; texels up to 1e4 never reach it).
Vec3h sample_half(const TextureH& texture, glm::dvec2 uv, bool guarded = true);

}  // namespace lt::fp16
