#include "paths/arbfp/arb_key.h"

#include <cmath>

#include "core/error.h"
#include "paths/arbfp/arb_albedo_map.h"
#include "paths/arbfp/arb_pack.h"

namespace lt::arbfp {

namespace {

bool is_integer_power(double p) {
  return p >= 1 && p == std::floor(p) && p <= 1 << 20;
}

// The lights in lane order: the scene's, or point lights first (stable).
LightList ordered_lights(const Scene& scene, bool by_kind, const LightNumbers& numbers) {
  LightList list = scene_lights(scene, numbers);
  if (!by_kind) return list;
  LightList out{{}, {}, list.eye};
  for (Light::Type t : {Light::Type::Point, Light::Type::Directional}) {
    for (size_t i = 0; i < list.size(); ++i) {
      if (list[i].type != t) continue;
      out.lights.push_back(list[i]);
      out.scene_index.push_back(list.scene_index[i]);
    }
  }
  return out;
}

// What every variant does on a lobe-ramp material (for `info`): the ramp is the curve.
std::string ramp_note(const PowVariant& variant, const TextureMap& ramp) {
  const std::string s = "lobe ramp " + ramp.file.filename().string() + " (" +
                        std::to_string(ramp.texture.width) + " texels, " +
                        (ramp.grey ? "grey" : "rgb") +
                        "): its value at t replaces t^p (power unused), one TEX per light from "
                        "texture[0]";
  if (variant.per_vertex) {
    return s +
           "; pow=mul:vertex: t per vertex (unsaturated, Gouraud-interpolated), the ramp per "
           "pixel";
  }
  return s + "; " + variant.name() + " has no curve to approximate on this material";
}

// Which groups are packed and which sum their colours by dot products, for `layout`.
void apply_layout(Key& k, const Layout& layout) {
  k.list = ordered_lights(k.scene, layout.by_kind, k.numbers);
  GuardNeeds lane_order = k.guards;
  for (size_t i = 0; i < k.lights; ++i) {
    size_t j = 0;  // the light's place in the scene's list
    while (light_number(k.numbers, j) != k.list.scene_index[i]) ++j;
    lane_order.distance_zero[i] = k.guards.distance_zero[j];
    lane_order.attenuation_floor[i] = k.guards.attenuation_floor[j];
  }
  k.guards = lane_order;
  // Not packed: the LUT (its TEX results take the per-light registers H and L, lobe_lut) and a
  // normalised H (|H| per light). A ramp packs t and reads the ramp light by light (lobe_ramp).
  const bool packable = (k.ramp_lobe || k.method != PowMethod::Lut) &&
                        !(k.fragment_lobe && k.tr.normalize_distorted_light);
  // The dot products read a group's lobe register, which the fragment program's own packed lobe
  // methods have (the LUT's, the ramp's, the vertex lobe's and the flat lobe's are not
  // temporaries of one scalar per light).
  const bool lobe_register =
      !k.term || (k.fragment_lobe && !k.ramp_lobe && k.method != PowMethod::Lut);
  for (size_t g = 0; g < k.groups; ++g) {
    const size_t n = lanes_of_group(g, k.lights);
    const bool packed = packable && n >= layout.pack_min && group_has_one_kind(k.list, g);
    k.packed.push_back(packed);
    k.dot_sums.push_back(packed && layout.dot_sums && n >= 3 && lobe_register);
    for (size_t i = g * 4; i < g * 4 + n && !packed; ++i) {
      k.per_light_h |= k.fragment_lobe;
      k.per_light_point |= k.list[i].type == Light::Type::Point;
    }
    if (!packed) continue;
    std::string lights;
    for (size_t i = g * 4; i < g * 4 + n; ++i) {
      lights += (lights.empty() ? "" : ", ") + std::to_string(k.list.scene_index[i]);
    }
    k.notes.push_back("lights " + lights + " packed four lanes to a register" +
                      (k.dot_sums.back() ? ", colour sums as dot products" : ""));
  }
  // A ramp material keeps V and its own lobe code (emit_ramp_lobe: t, one TEX per light, then
  // lobe * s + a): t from interpolated dots and s folded into T are written for t^p.
  k.view_dots = layout.view_dots && k.fragment_lobe && !k.ramp_lobe && !k.ortho &&
                !k.tr.normalize_distorted_light && k.method != PowMethod::Lut &&
                k.lights <= static_cast<size_t>(kFreeTexcoords) && !any_of(k.packed);
  for (size_t i = 0; i < k.lights; ++i) {
    k.view_dots &= k.list[i].type == Light::Type::Directional;
  }
  if (k.view_dots) k.per_light_h = false;
  k.packed_view_dots = layout.view_dots && k.fragment_lobe && !k.ramp_lobe && !k.ortho &&
                       !k.tr.normalize_distorted_light && k.method != PowMethod::Lut &&
                       k.groups + 1 <= static_cast<size_t>(kFreeTexcoords) && k.groups > 0;
  for (size_t g = 0; g < k.groups; ++g) k.packed_view_dots &= k.packed[g];
  k.fold_scale = layout.fold_scale && k.fragment_lobe && !k.ramp_lobe && k.method == PowMethod::Mul;
  // A light summed alone folds s into s * T: a PARAM for a constant T; for a vertex T the vertex
  // program's product, one texcoord per light (none of them summed by dot products, which read
  // the unscaled T).
  const size_t free_texcoords = kFreeTexcoords - k.view_dot_texcoords();
  k.vertex_scaled_T =
      k.vertex_thickness && !any_of(k.dot_sums) && k.lights >= 1 && k.lights - 1 <= free_texcoords;
  for (size_t g = 0; g < k.groups; ++g) {
    k.fold_scale &=
        k.dot_sums[g] || k.tr.thickness_source == ThicknessSource::Constant || k.vertex_scaled_T;
  }
  for (size_t i = 0; i < k.lights; ++i) k.fold_scale &= k.list[i].translucency_scale > 0;
  k.vertex_scaled_T &= k.fold_scale;
}

}  // namespace

Key make_key(const Scene& scene, const Material& material, const PowVariant& variant,
             bool translucency_term, const Layout& layout, const LightNumbers& numbers,
             const GuardNeeds& guards) {
  Key k{scene, material.translucency.value_or(Translucency{}), variant};
  k.term = translucency_term && material.translucency.has_value();
  k.lights = scene.lights.size();
  k.groups = group_count(k.lights);
  k.vertex_thickness = k.term && k.tr.thickness_source == ThicknessSource::Vertex;
  k.map_thickness = k.term && k.tr.thickness_source == ThicknessSource::Texture;
  check_albedo_map_texcoord(material, scene.file.string());
  k.albedo_map = material.albedo_map != nullptr;
  k.ortho = scene.camera.projection == Camera::Projection::Orthographic;
  k.ambient = scene.ambient_light != glm::dvec3(0);
  k.ramp_lobe = k.term && k.tr.ramp != nullptr;
  k.flat_lobe = k.term && !lobe_varies(k.tr);
  for (const Light& l : scene.lights) k.any_point |= l.type == Light::Type::Point;
  k.vertex_lobe = k.term && !k.flat_lobe && variant.per_vertex;
  k.fragment_lobe = k.term && !k.flat_lobe && !k.vertex_lobe;
  if (k.vertex_lobe && k.lights > kMaxVertexLobeLights) {
    throw InputError("--variant", variant.name(),
                     "the per-vertex lobe takes at most " + std::to_string(kMaxVertexLobeLights) +
                         " lights (four per texcoord, texcoord[3..7]); the scene has " +
                         std::to_string(k.lights));
  }
  k.method = variant.method;
  if (k.term && !k.flat_lobe && !k.ramp_lobe && k.method == PowMethod::Mul &&
      !is_integer_power(k.tr.power)) {
    k.notes.push_back(variant.name() + ": power " + ir::num(k.tr.power) +
                      " is not an integer, exact POW used instead" +
                      (variant.per_vertex ? " (per vertex)" : ""));
    k.method = PowMethod::Exact;
  }
  if (k.flat_lobe) k.notes.push_back("power 0: the lobe is 1 everywhere (0^0 := 1), no pow");
  if (k.ramp_lobe) k.notes.push_back(ramp_note(variant, *k.tr.ramp));
  k.numbers = numbers;
  k.guards = guards;
  for (const std::string& n : k.guards.notes) k.notes.push_back(n);
  apply_layout(k, layout);
  if (k.vertex_lobe && !k.ramp_lobe) {
    k.notes.push_back(std::string("pow=mul:vertex: t and the lobe per vertex, Gouraud-") +
                      "interpolated" + (k.any_point ? " (point lights: L at the vertex too)" : ""));
  }
  return k;
}

}  // namespace lt::arbfp
