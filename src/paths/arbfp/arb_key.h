// The arbfp generator's state key (Mesa's state key, e.g. st_fp_variant_key): what the scene, the
// material and the variant ask of the two programs, decided once by make_key and then read,
// never written, by the vertex and fragment generators (arb_vertex_program.h,
// arb_fragment_program.h). Internal to the generator (arb_generator.cpp).
#pragma once

#include <algorithm>
#include <string>
#include <vector>

#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_generator.h"
#include "paths/arbfp/arb_guards.h"
#include "paths/arbfp/arb_variant.h"
#include "paths/arbfp/arb_view_dots.h"
#include "scene/scene.h"

namespace lt::arbfp {

// How the fragment program lays out the lights (generate_arb tries each and keeps the shortest
// program: packing pays for groups of three or four lights, not for one).
struct Layout {
  bool by_kind = false;   // point lights first, then directional ones: groups of one kind
  size_t pack_min = 5;    // a group of one kind with at least this many lights is packed (5: none)
  bool dot_sums = false;  // packed groups of three or four lights sum their colours by DP4/DP3
  bool fold_scale = false;  // Key::fold_scale where it applies
  bool view_dots = false;   // Key::view_dots where it applies
};

// What the scene, the material and the variant ask of the two programs, decided once (Mesa's
// state key): the generators take it const.
struct Key {
  const Scene& scene;
  const Translucency tr;  // the material's, or the defaults when it has none
  const PowVariant& variant;
  bool term = false;              // the translucency term is generated
  bool flat_lobe = false;         // p = 0: t^0 = 1 everywhere (0^0 := 1), no t and no lobe
  bool vertex_lobe = false;       // pow=mul:vertex: the vertex program computes t and the lobe
                                  // (t only with ramp_lobe: the fragment program reads the ramp)
  bool fragment_lobe = false;     // the fragment program computes t and the lobe
  bool ramp_lobe = false;         // the material's ramp replaces t^p in every variant (lobe_ramp)
  bool vertex_thickness = false;  // T comes from the vertex colour
  bool map_thickness = false;     // T comes from a thickness map (arb_thickness_map.h)
  bool albedo_map = false;        // the albedo is a map's texel times albedo (arb_albedo_map.h)
  bool ortho = false, ambient = false, any_point = false;
  size_t lights = 0, groups = 0;
  PowMethod method = PowMethod::Exact;  // the variant's, after pow=mul's fallback
  GuardNeeds guards = {};               // the fragment program's, for this scene, in lane order
  std::vector<std::string> notes =
      {};                         // what the key decided (for `info`); the generators add theirs
  LightNumbers numbers = {};      // the lights' numbers in the whole scene (a pass's, arb_passes.h)
  LightList list = {};            // the lights in lane order
  std::vector<bool> packed = {};  // per group: the light loop four lanes at a time (arb_pack.h)
  std::vector<bool> dot_sums = {};  // per group: the colour sums as dot products
  bool per_light_h = false;         // some light computes its own H (the register H is declared)
  bool per_light_point = false;     // some point light computes its own L (the register L)
  // pow=mul: lobe * s + a is (lobe + a / s) * s, the addend on the chain's last MUL and s in
  // the per-light s * T (constant T, or a vertex T times s in the vertex program) or in the
  // colours of the dot products; needs every s > 0.
  bool fold_scale = false;
  // Directional lights' t from the interpolated (d P, P.L) (arb_view_dots.h): every light
  // directional and computed alone, a perspective camera, H not normalised.
  bool view_dots = false;
  // Every light in a packed group, t from the interpolated d P (texcoord[3]) and per-group dots
  // (texcoord[4 + g]) without V (arb_view_dots.h).
  bool packed_view_dots = false;
  // fold_scale with a vertex thickness: the vertex program writes s * T per light (texcoord[2]
  // for the first light, free texcoords after the view dots for the others).
  bool vertex_scaled_T = false;

  int view_dot_texcoord(size_t light) const { return kFirstFreeTexcoord + static_cast<int>(light); }
  int distorted_position_texcoord() const { return kFirstFreeTexcoord; }
  int group_view_dot_texcoord(size_t group) const {
    return kFirstFreeTexcoord + 1 + static_cast<int>(group);
  }
  size_t view_dot_texcoords() const {
    return view_dots ? lights : packed_view_dots ? groups + 1 : 0;
  }
  int scaled_T_texcoord(size_t light) const {
    if (light == 0) return 2;
    return kFirstFreeTexcoord + static_cast<int>(view_dot_texcoords() + light - 1);
  }
};

// The key for one layout of the lights (generate_arb tries several, arb_generator.cpp), with the
// guards guard_needs found for the material and the variant's :guards (they do not depend on the
// layout, and finding them scans every triangle: generate_arb finds them once). Throws
// InputError("--variant", ...) when the per-vertex lobe has more lights than texcoords.
Key make_key(const Scene& scene, const Material& material, const PowVariant& variant,
             bool translucency_term, const Layout& layout, const LightNumbers& numbers,
             const GuardNeeds& guards);

inline bool any_of(const std::vector<bool>& v) {
  return std::find(v.begin(), v.end(), true) != v.end();
}

inline size_t lanes_of_group(size_t g, size_t lights) {
  return std::min<size_t>(4, lights - g * 4);
}

// Light group g's texcoord from the vertex program to the fragment program (pow=mul:vertex).
inline std::string vertex_lobe_texcoord(size_t group) {
  return "texcoord[" + std::to_string(kVertexLobeTexcoord + group) + "]";
}

}  // namespace lt::arbfp
