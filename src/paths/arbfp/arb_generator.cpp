#include "paths/arbfp/arb_generator.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "core/error.h"
#include "paths/arbfp/arb_albedo_map.h"
#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_guards.h"
#include "paths/arbfp/arb_ir_counter.h"
#include "paths/arbfp/arb_lobe.h"
#include "paths/arbfp/arb_pack.h"
#include "paths/arbfp/arb_thickness_map.h"
#include "paths/arbfp/arb_view_dots.h"

namespace lt::arbfp {

using ir::attrib;
using ir::Op;
using ir::output;
using ir::Reg;

namespace {

// The programs' own description, at their top (what `ltrender info --source` shows).
const char kFragmentHeader[] =
    R"(# arbfp path, fragment program: the equation of model.md per pixel in ARB_fragment_program
# assembly (the SM2 model). Generated per material by src/paths/arbfp/arb_generator.cpp, which
# emits only what the scene uses: one block per light (attenuation only for point lights), the
# view vector and thickness only when the translucency term reads them, ambient only when
# non-zero. Lights are packed four to a register (component x, y, z, w of diffuse0, tv0, lobe0,
# att0; then diffuse1 ...) so the lobe t^p, or its replacement, runs once per group of four.
#
# Inputs from translucency.vp:
#   fragment.texcoord[0]  camera-relative position P (the eye is the origin)
#   fragment.texcoord[1]  interpolated normal (not unit)
#   fragment.texcoord[2]  vertex thickness (only when the material reads it), or the UVs of
#                          a thickness map (texture[1])
#   fragment.texcoord[3+g] pow=mul:vertex only: (lobe * s + a) of light group g, per vertex
#                          (then the fragment program has no t, V, H or lobe of its own); on a
#                          lobe-ramp material t of light group g, which the ramp's TEX reads
#
)";

const char kVertexHeader[] =
    "# arbfp path, vertex program: shading is per pixel, so this mostly hands the fragment program "
    "what\n"
    "# it reads. Generated per material by src/paths/arbfp/arb_generator.cpp: the thickness line "
    "and,\n"
    "# for pow=mul:vertex only, the translucency lobe per vertex (into texcoord[3..7], four lights "
    "per\n"
    "# texcoord) are the parts that vary.\n"
    "#\n"
    "# ARB_position_invariant: the position is transformed by the fixed-function "
    "MODELVIEW/PROJECTION\n"
    "# exactly as ftransform() and fixed-function do, so every path rasterises the same pixels.\n";

bool is_integer_power(double p) {
  return p >= 1 && p == std::floor(p) && p <= 1 << 20;
}

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
// state key): the generators below only read it.
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
  std::vector<std::string> notes = {};
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

bool any_of(const std::vector<bool>& v) {
  return std::find(v.begin(), v.end(), true) != v.end();
}

size_t lanes_of_group(size_t g, size_t lights) {
  return std::min<size_t>(4, lights - g * 4);
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

// Light group g's texcoord from the vertex program to the fragment program (pow=mul:vertex).
std::string vertex_lobe_texcoord(size_t group) {
  return "texcoord[" + std::to_string(kVertexLobeTexcoord + group) + "]";
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

Key make_key(const Scene& scene, const Material& material, const PowVariant& variant,
             bool translucency_term, const Layout& layout, const LightNumbers& numbers) {
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
  k.guards = guard_needs(scene, material, variant.all_guards, numbers);
  for (const std::string& n : k.guards.notes) k.notes.push_back(n);
  apply_layout(k, layout);
  if (k.vertex_lobe && !k.ramp_lobe) {
    k.notes.push_back(std::string("pow=mul:vertex: t and the lobe per vertex, Gouraud-") +
                      "interpolated" + (k.any_point ? " (point lights: L at the vertex too)" : ""));
  }
  return k;
}

// ---- The vertex program ----------------------------------------------------------------------

// pow=mul:vertex: N, V, L, H, t = saturate(dot(V, -H)), the lobe t^p and (lobe * s + a) per
// vertex, into texcoord[kVertexLobeTexcoord + g] (lobe * s + a is linear in the lobe, so
// interpolating it equals applying it to the interpolated lobe). Every hard-case convention of
// src/model/translucency.h holds at the vertices; between them the lobe is Gouraud-interpolated
// (also for point lights, whose L is taken at the vertex here, like the combiners path), which is
// this variant's error. On a lobe-ramp material only t, unsaturated: the fragment program reads
// the ramp at the interpolated t, whose CLAMP_TO_EDGE saturates it per pixel as the model does
// (saturating per vertex would move the lobe's edge).
void emit_vertex_lobe(ir::Program& p, Key& k) {
  ir::Block decls = p.block(), temps = p.block(), code = p.block();
  decls.text(k.ramp_lobe
                 ? "# t per vertex (pow=mul:vertex on a lobe-ramp material): the fragment program\n"
                   "# reads the ramp at the interpolated t.\n"
                 : "# The translucency lobe per vertex (pow=mul:vertex): the fragment program only "
                   "adds\n# lobe * T to the diffuse term of each light.\n");
  Shading s;
  s.P = attrib("vertex.position");
  s.material = declare_material(decls, k.tr);
  s.guard = declare_guards(decls);
  if (k.ortho) s.V = declare_orthographic_view(decls, k.scene);
  std::vector<Reg> light_vector, scale;
  for (size_t i = 0; i < k.lights; ++i) {
    light_vector.push_back(declare_light_vector(decls, k.list, i));
  }
  for (size_t g = 0; g < k.groups && !k.ramp_lobe; ++g) {
    scale.push_back(declare_scale(decls, k.list, g));
  }

  s.r = p.temp("r");
  s.N = p.temp("N");
  s.H = p.temp("H");
  if (!k.ortho) s.V = p.temp("V");
  if (k.any_point) s.L = p.temp("L");
  std::vector<Reg> tv, lobe;
  for (size_t g = 0; g < k.groups; ++g) {
    if (k.ramp_lobe) {
      tv.push_back(output("result." + vertex_lobe_texcoord(g)));  // t goes out as it is
      continue;
    }
    tv.push_back(p.temp("tv" + std::to_string(g)));
    lobe.push_back(p.temp("lobe" + std::to_string(g)));
  }
  temps.temps();

  code.text("# N = n / |n|, or 0 when |n| < 1e-6 (then H = L, as the reference).\n");
  emit_normal(code, s, attrib("vertex.normal"));
  if (!k.ortho) emit_view_vector(code, s);
  if (k.ramp_lobe)
    code.text("# t = dot(V, -H) of each light, unsaturated, to the fragment program.\n");
  for (size_t i = 0; i < k.lights; ++i) {
    const Reg L = emit_light_direction(code, s, k.list, i, light_vector[i]);
    emit_t(code, s, L, k.tr.normalize_distorted_light, write_lane(tv, i));
  }
  if (k.ramp_lobe) {
    code.text("\n");
    return;
  }
  code.text("# t = saturate(dot(V, -H)) for a whole group at once (no _SAT in vertex programs).\n");
  for (size_t g = 0; g < k.groups; ++g) {
    const Reg dst = tv[g].masked(group_mask(g, k.lights));
    code.op(Op::MAX, dst, {tv[g], s.material.zero});
    code.op(Op::MIN, dst, {tv[g], s.guard.one});
  }
  LobeInput in{decls, code, s, k.variant, k.tr, k.lights, tv, lobe, k.notes, {}};
  lobe_mul_vertex(in, k.method);
  code.text("# lobe * s + a, to the fragment program.\n");
  for (size_t g = 0; g < k.groups; ++g) {
    const Reg out = output("result." + vertex_lobe_texcoord(g));
    emit_scale_and_ambient(code, out.masked(group_mask(g, k.lights)), lobe[g], scale[g], s.material,
                           k.tr.ambient != 0);
  }
  code.text("\n");
}

// Shading is per pixel: the vertex program hands the fragment program the camera-relative
// position, the normal and, when the material reads it, the vertex thickness.
ir::Program vertex_program(Key& k) {
  ir::Program p(ir::ProgramKind::Vertex);
  ir::Block b = p.block();
  b.text(kVertexHeader);
  b.option("ARB_position_invariant");
  b.text(
      "# Camera-relative position (the eye is the origin: src/gl/scene_geometry.h) and the world "
      "normal,\n# through texture coordinates because colour varyings may be clamped to [0, 1].\n");
  b.op(Op::MOV, output("result.texcoord[0]"), {attrib("vertex.position")});
  b.op(Op::MOV, output("result.texcoord[1]"), {attrib("vertex.normal")});
  if (k.vertex_scaled_T) {
    // s * T = vertex colour * (s * tint) per light: s and the tint are constant, so
    // interpolating the product equals the product of the interpolation, and the fragment
    // program saves the MUL by s (fold_scale) without a PARAM s * T it cannot have.
    b.text("# Vertex thickness times each light's s: the mesh colour times s * tint.\n");
    for (size_t i = 0; i < k.lights; ++i) {
      const Reg tint = b.param(k.list.name(i) + "_s_tint",
                               vec4(k.list[i].translucency_scale * k.tr.tint, 0), "s * tint");
      const std::string out = "result.texcoord[" + std::to_string(k.scaled_T_texcoord(i)) + "]";
      b.op(Op::MUL, output(out), {attrib("vertex.color"), tint});
    }
  } else if (k.vertex_thickness) {
    // T = vertex colour * tint is multiplied here: the tint is constant, so interpolating the
    // product equals the product of the interpolation, and the fragment program saves one MUL
    // per pixel.
    b.text("# Vertex thickness: the mesh colour times the material's tint.\n");
    const Reg tint = b.param("tint", vec4(k.tr.tint, 0));
    b.op(Op::MUL, output("result.texcoord[2]"), {attrib("vertex.color"), tint});
  } else if (!k.map_thickness && !k.albedo_map) {
    b.text("# (constant thickness: nothing more to pass)\n");
  }
  // The UVs, once, for the thickness map and the albedo map alike.
  if (k.map_thickness || k.albedo_map) emit_map_uv(b);
  if (k.view_dots) {
    b.text("# (d P, P.L) per directional light, linear in P: interpolated exactly.\n");
    const Reg d = declare_material(b, k.tr).distortion;
    for (size_t i = 0; i < k.lights; ++i) {
      const std::string out = "result.texcoord[" + std::to_string(k.view_dot_texcoord(i)) + "]";
      emit_view_dot_varying(b, output(out), attrib("vertex.position"), d,
                            declare_light_vector(b, k.list, i));
    }
  }
  if (k.packed_view_dots) {
    b.text("# d P, and per group P.L or P.position in each light's lane: linear in P.\n");
    const Reg d = declare_material(b, k.tr).distortion;
    const auto texcoord = [](int t) {
      return output("result.texcoord[" + std::to_string(t) + "]");
    };
    emit_distorted_position(b, texcoord(k.distorted_position_texcoord()), attrib("vertex.position"),
                            d);
    for (size_t g = 0; g < k.groups; ++g) {
      std::vector<Reg> vectors;
      for (size_t i = g * 4; i < g * 4 + lanes_of_group(g, k.lights); ++i) {
        vectors.push_back(declare_light_vector(b, k.list, i));
      }
      emit_group_view_dots(b, texcoord(k.group_view_dot_texcoord(g)), attrib("vertex.position"),
                           vectors);
    }
  }
  if (k.vertex_lobe) {
    emit_vertex_lobe(p, k);
  } else {
    p.block().text("# (the lobe is computed per pixel)\n");
  }
  return p;
}

// ---- The fragment program --------------------------------------------------------------------

// The fragment program's blocks (in print order) and registers.
struct Fragment {
  explicit Fragment(ir::Program& prog)
      : p(prog), head(p.block()), decls(p.block()), temps(p.block()), code(p.block()) {}
  ir::Program& p;
  ir::Block head, decls, temps, code;
  Shading s;
  Reg albedo, sum, T, ambient;
  Reg albedo_rgb;        // what the sum is multiplied by: the albedo, or the albedo map's A
  Reg dnv;               // sum.w = d * (N.V), for the packed groups' t
  std::array<Reg, 3> d;  // packed point groups: position - P, x y z
  Reg dist2, one;        // packed point groups without lobe registers
  std::vector<Reg> diffuse, tv, lobe, att;        // per group
  std::vector<PackedRows> rows;                   // per packed group
  std::vector<std::array<Reg, 3>> colour_rows;    // per group summed by dot products
  std::vector<Reg> color, light_vector, light_k;  // per light not packed (invalid otherwise)
  std::vector<Reg> scaled_T;                      // per light summed alone: s * T (fold_scale)
  std::vector<std::array<Reg, 3>> scaled_rows;    // per group summed by dot products: s * colour
  // A temporary declared on first use: acc, the per-light sum's term (and the dot products'
  // second sum when no packed point group left its scratch).
  Reg acc() {
    if (!acc_.valid()) acc_ = p.temp("acc");
    return acc_;
  }

 private:
  Reg acc_;
};

// The ambient light goes into the final multiply when the first group sums by dot products
// (which have no addend): (sum + ambient) * albedo = sum * albedo + ambient * albedo.
bool ambient_after_sum(const Key& k) {
  return k.ambient && k.groups > 0 && k.dot_sums[0];
}
// With an albedo map the albedo is a texel, not a PARAM, so ambient * albedo is no constant: the
// ambient light is added to the sum first (one ADD) and the final multiply is a MUL.
bool ambient_in_final(const Key& k) {
  return ambient_after_sum(k) && !k.albedo_map;
}

// Declarations in print order (the TEMP statement lists the temporaries in allocation order).
void declare_fragment(Fragment& f, const Key& k, const Material& material) {
  ir::Program& p = f.p;
  ir::Block& d = f.decls;
  d.text("# albedo.w = 1 is the output alpha (coverage for the comparison).\n");
  f.albedo = d.param("albedo", vec4(material.albedo, 1));
  f.albedo_rgb = k.albedo_map ? emit_albedo_map(p, d, f.code, material.albedo) : f.albedo;
  f.s.guard = declare_guards(d);
  f.s.zero_normal_guard = k.guards.zero_normal;
  f.s.P = attrib("fragment.texcoord[0]");
  f.s.r = p.temp("r");
  f.s.N = p.temp("N");
  f.sum = p.temp("sum");
  if (k.per_light_h) f.s.H = p.temp("H");
  if (k.per_light_point) f.s.L = p.temp("L");
  for (size_t g = 0; g < k.groups; ++g) {
    const std::string n = std::to_string(g);
    f.diffuse.push_back(p.temp("diffuse" + n));
    if (k.fragment_lobe) f.tv.push_back(p.temp("tv" + n)), f.lobe.push_back(p.temp("lobe" + n));
    if (k.any_point) f.att.push_back(p.temp("att" + n));
  }
  bool packed_point = false;
  for (size_t g = 0; g < k.groups; ++g) {
    packed_point |= k.packed[g] && k.list[g * 4].type == Light::Type::Point;
  }
  if (packed_point) {
    f.d = {p.temp("d_x"), p.temp("d_y"), p.temp("d_z")};
    if (!k.fragment_lobe) f.dist2 = p.temp("dist2");
  }
  if (k.term) {
    if (k.vertex_lobe) {
      d.text(std::string("# pow=mul:vertex: ") + (k.ramp_lobe ? "t" : "(lobe * s + a)") +
             " of light group g comes in fragment.texcoord[" + std::to_string(kVertexLobeTexcoord) +
             " + g]\n");
    }
    // A ramp's lobe * s + a is the fragment program's, whichever program computed t.
    if (!k.vertex_lobe || k.ramp_lobe) f.s.material = declare_material(d, k.tr);
    if (k.vertex_scaled_T) {
      d.text(
          "# s * T of light i = its texcoord (vertex colour * s * tint, see the vertex program)\n");
    } else if (k.vertex_thickness) {
      // The vertex program multiplied the tint in (see there).
      d.text("# T = fragment.texcoord[2]: vertex colour * tint\n");
      f.T = attrib("fragment.texcoord[2]");
    } else if (k.map_thickness) {
      f.T = emit_map_thickness(p, d, f.code, k.tr.tint);
    } else if (!k.fold_scale || any_of(k.dot_sums)) {
      // (With the scale folded, a light summed alone reads its own s * T instead.)
      d.text("# constant thickness * tint\n");
      f.T = d.param("T", vec4(k.tr.thickness * k.tr.tint, 0));
    }
    if (k.fragment_lobe) f.s.V = k.ortho ? declare_orthographic_view(d, k.scene) : p.temp("V");
  }
  if (k.ambient && !ambient_in_final(k)) {
    f.ambient = d.param("ambient_light", vec4(k.scene.ambient_light, 0));
  }
  f.color.resize(k.lights);
  f.light_vector.resize(k.lights);
  f.light_k.resize(k.lights);
  f.scaled_T.resize(k.lights);
  f.scaled_rows.resize(k.groups);
  f.rows.resize(k.groups);
  f.colour_rows.resize(k.groups);
  for (size_t g = 0; g < k.groups; ++g) {
    if (k.packed[g]) f.rows[g] = declare_packed_rows(d, k.list, g);
    if (k.dot_sums[g]) f.colour_rows[g] = declare_colour_rows(d, k.list, g, false);
    if (k.dot_sums[g] && k.fold_scale) f.scaled_rows[g] = declare_colour_rows(d, k.list, g, true);
    for (size_t i = g * 4; i < g * 4 + lanes_of_group(g, k.lights); ++i) {
      const Light& l = k.list[i];
      const std::string prefix = k.list.name(i) + "_";
      if (!k.dot_sums[g]) f.color[i] = d.param(prefix + "color", vec4(l.color, 0));
      if (k.vertex_scaled_T) {
        f.scaled_T[i] = attrib("fragment.texcoord[" + std::to_string(k.scaled_T_texcoord(i)) + "]");
      } else if (!k.dot_sums[g] && k.fold_scale) {
        f.scaled_T[i] = d.param(
            prefix + "sT", vec4(l.translucency_scale * k.tr.thickness * k.tr.tint, 0), "s * T");
      }
      if (k.packed[g]) continue;
      f.light_vector[i] = declare_light_vector(d, k.list, i);
      if (l.type == Light::Type::Point) {
        f.light_k[i] = d.param(prefix + "k", ir::vec4(l.kc, l.kl, l.kq, 0), "kc, kl, kq");
      }
    }
  }
}

// att = 1 / max(kc + kl dist + kq dist^2, kMinAttenuationDenominator), from the r.x = 1/dist
// that emit_point_light_direction left.
void emit_attenuation(ir::Block& code, const Shading& s, const Reg& k, const Reg& att, bool floor) {
  const Reg& r = s.r;
  code.text("# dist = 1 / RSQ(dist^2): RCP(+inf) = 0, so no NaN at distance 0.\n");
  code.op(Op::RCP, r.masked("y"), {r.swz("x")});
  code.op(Op::MAD, r.masked("z"), {r.swz("y"), k.swz("y"), k.swz("x")});
  code.op(Op::MAD, r.masked("z"), {s.L.swz("w"), k.swz("z"), r.swz("z")});
  if (floor) code.op(Op::MAX, r.masked("z"), {r.swz("z"), s.guard.attenuation_min});
  code.op(Op::RCP, att, {r.swz("z")});
}

// Light i on its own: diffuse (and attenuation), then t.
void fragment_light(Fragment& f, const Key& k, size_t i) {
  ir::Block& code = f.code;
  const Reg L =
      emit_light_direction(code, f.s, k.list, i, f.light_vector[i], k.guards.distance_zero[i]);
  if (k.list[i].type == Light::Type::Point) {
    emit_attenuation(code, f.s, f.light_k[i], write_lane(f.att, i), k.guards.attenuation_floor[i]);
  }
  code.op_sat(Op::DP3, write_lane(f.diffuse, i), {f.s.N, L});
  if (k.view_dots) {
    const std::string varying = std::to_string(k.view_dot_texcoord(i));
    emit_view_dot_t(code, f.s.N, attrib("fragment.texcoord[" + varying + "]"), f.s.V.swz("w"),
                    read_lane(f.tv, i));
  } else if (k.fragment_lobe) {
    emit_t(code, f.s, L, k.tr.normalize_distorted_light, write_lane(f.tv, i));
  }
}

// The lanes of group g whose light needs a guard (`needs` in lane order).
std::string guarded_lanes(const std::vector<bool>& needs, size_t g, size_t lights) {
  std::string lanes;
  for (size_t i = g * 4; i < g * 4 + lanes_of_group(g, lights); ++i) {
    if (needs[i]) lanes += component(i);
  }
  return lanes;
}

// Group g four lanes at a time (arb_pack.h).
void fragment_packed_group(Fragment& f, const Key& k, size_t g) {
  PackedGroup pg;
  pg.mask = group_mask(g, k.lights);
  pg.point = k.list[g * 4].type == Light::Type::Point;
  pg.diffuse = f.diffuse[g];
  if (k.fragment_lobe) pg.tv = f.tv[g];
  pg.dnv = f.dnv;
  if (k.packed_view_dots) {
    pg.view_dots =
        attrib("fragment.texcoord[" + std::to_string(k.group_view_dot_texcoord(g)) + "]");
    pg.eye = f.s.V;
    pg.view_addend = f.dnv;
  }
  if (pg.point) {
    pg.att = f.att[g];
    pg.d = f.d;
    pg.d2 = k.fragment_lobe ? f.lobe[g] : f.dist2;
    pg.inv = f.s.r;
    pg.distance_zero_lanes = guarded_lanes(k.guards.distance_zero, g, k.lights);
    pg.floor_lanes = guarded_lanes(k.guards.attenuation_floor, g, k.lights);
    if (!pg.distance_zero_lanes.empty()) {
      if (!f.one.valid()) f.one = f.decls.param("one", "{1, 0, 0, 0}", "L = N: 1/dist := 1");
      pg.one = f.one;
    }
  }
  std::string names;
  for (size_t i = g * 4; i < g * 4 + lanes_of_group(g, k.lights); ++i) {
    names += (names.empty() ? "" : ", ") + std::to_string(k.list.scene_index[i]);
  }
  f.code.text("# lights " + names + ": " + (pg.point ? "point" : "directional") +
              ", packed in lanes " + pg.mask + "\n");
  emit_packed_group(f.code, f.s, f.rows[g], pg);
}

// Per group: diffuse (and attenuation), then t, for each light or four lanes at a time.
void fragment_lights(Fragment& f, const Key& k) {
  ir::Block& code = f.code;
  code.text(
      "\n# Per light: diffuse (and attenuation), then t = saturate(dot(V, -H)) with H = L + "
      "N*d.\n");
  if (k.packed_view_dots) {
    f.dnv = f.sum.swz("w");
    const std::string dp = std::to_string(k.distorted_position_texcoord());
    emit_eye_terms(code, f.s.P, f.s.N, attrib("fragment.texcoord[" + dp + "]"), f.s.V, f.dnv,
                   k.any_point);
  } else if (k.fragment_lobe && any_of(k.packed)) {
    code.text("# The packed groups' t reads d * (N.V) from sum.w (sum is xyz until the end).\n");
    f.dnv = f.sum.swz("w");
    code.op(Op::DP3, f.sum.masked("w"), {f.s.N, f.s.V});
    code.op(Op::MUL, f.sum.masked("w"), {f.dnv, f.s.material.distortion});
  }
  for (size_t g = 0; g < k.groups; ++g) {
    if (k.packed[g]) {
      fragment_packed_group(f, k, g);
      continue;
    }
    for (size_t i = g * 4; i < g * 4 + lanes_of_group(g, k.lights); ++i) fragment_light(f, k, i);
  }
}

// Each light's lobe as the accumulation reads it.
struct FragmentLobe {
  LobeLanes lanes;
  // The LUT's and the ramp's lanes hold the lobe and are scaled light by light in the
  // accumulation (these are the scales, per group); every other lobe arrives as lobe * s + a
  // (empty).
  std::vector<Reg> scale_in_accumulation;
};

LobeLanes fragment_method(LobeInput& in, PowMethod method, const model::PowerLut* lut) {
  switch (method) {
    case PowMethod::Exact:
      return lobe_exact(in);
    case PowMethod::Lut:
      return lobe_lut(in, *lut);
    case PowMethod::Sg:
      return lobe_sg(in);
    case PowMethod::SgSimplified:
      return lobe_sg_simplified(in);
    case PowMethod::SgFitted:
      return lobe_sg_fitted(in);
    case PowMethod::Mul:
      return lobe_mul(in);
  }
  return {};
}

// Light i's lane of what the vertex program passed (pow=mul:vertex): lobe * s + a, or t.
Reg vertex_lobe_lane(size_t light) {
  return attrib("fragment." + vertex_lobe_texcoord(light / 4)).swz(component(light));
}

// Temporaries dead once every light's t, diffuse and attenuation are known (the lobe's TEX
// results may take them; the accumulation reads none of them): each group's lobe register (a
// packed point group's dist^2 scratch until then), the per-light H and L, the scratch r, a packed
// point group's position - P, the normal and the view vector.
std::vector<Reg> lobe_scratch(const Fragment& f) {
  std::vector<Reg> out = f.lobe;
  for (const Reg& r : {f.s.H, f.s.r, f.s.L, f.d[0], f.d[1], f.d[2], f.s.N, f.s.V}) {
    if (r.valid() && r.file == ir::File::Temp) out.push_back(r);
  }
  return out;
}

// A lobe-ramp material, whatever the variant: the ramp at each light's t (computed here, or per
// vertex by pow=mul:vertex), scaled light by light in the accumulation (the lobe is rgb).
FragmentLobe emit_ramp_lobe(Fragment& f, const Key& k) {
  std::vector<Reg> t;
  for (size_t i = 0; i < k.lights; ++i) {
    t.push_back(k.vertex_lobe ? vertex_lobe_lane(i) : read_lane(f.tv, i));
  }
  FragmentLobe out;
  out.lanes = lobe_ramp(f.code, t, lobe_scratch(f));
  for (size_t g = 0; g < k.groups; ++g) {
    out.scale_in_accumulation.push_back(declare_scale(f.decls, k.list, g));
  }
  return out;
}

// The lobe t^p for every light, by the variant's method, then lobe * s + a per group.
FragmentLobe emit_lobe(Fragment& f, Key& k, std::optional<model::PowerLut>& lut) {
  if (k.ramp_lobe) return emit_ramp_lobe(f, k);
  f.code.text("\n# The lobe t^p for every light of a group at once, then (lobe * s + a).\n");
  FragmentLobe out;
  LobeLanes& lanes = out.lanes;
  if (k.vertex_lobe) {
    f.code.text("# pow=mul:vertex: the lobe, times s plus a, was computed per vertex.\n");
    for (size_t i = 0; i < k.lights; ++i) lanes.push_back(vertex_lobe_lane(i));
    return out;
  }
  if (!k.term) return out;
  if (k.flat_lobe) {
    for (size_t g = 0; g < k.groups; ++g) {
      const std::array<double, 4> s = light_scales(k.list, g);
      const double a = k.tr.ambient;
      f.lobe.push_back(f.decls.param("lobe" + std::to_string(g),
                                     ir::vec4(s[0] + a, s[1] + a, s[2] + a, s[3] + a),
                                     "1 * s + a (flat lobe)"));
    }
    for (size_t i = 0; i < k.lights; ++i) lanes.push_back(read_lane(f.lobe, i));
    return out;
  }
  LobeInput in{f.decls, f.code, f.s,     k.variant, k.tr,           k.lights,
               f.tv,    f.lobe, k.notes, {},        lobe_scratch(f)};
  if (k.fold_scale && k.tr.ambient != 0) {
    // lobe * s + a = (lobe + a / s) * s: a / s rides on the chain's last MUL, s on T or on
    // the colours the sum reads.
    for (size_t g = 0; g < k.groups; ++g) {
      const std::array<double, 4> s = light_scales(k.list, g);
      std::array<double, 4> v = {0, 0, 0, 0};
      for (size_t i = 0; i < lanes_of_group(g, k.lights); ++i) v[i] = k.tr.ambient / s[i];
      in.addend.push_back(f.decls.param("a_over_s" + std::to_string(g),
                                        ir::vec4(v[0], v[1], v[2], v[3]), "a / s per light"));
    }
  }
  if (k.method == PowMethod::Lut) {
    lut = model::PowerLut::build(k.variant.lut_size, k.variant.lut_format, {k.tr.power});
  }
  lanes = fragment_method(in, k.method, lut ? &*lut : nullptr);
  if (k.fold_scale) return out;
  std::vector<Reg> scale;
  for (size_t g = 0; g < k.groups; ++g) scale.push_back(declare_scale(f.decls, k.list, g));
  if (k.method == PowMethod::Lut) {
    out.scale_in_accumulation = scale;
    return out;
  }
  for (size_t g = 0; g < k.groups; ++g) {
    emit_scale_and_ambient(f.code, f.lobe[g].masked(group_mask(g, k.lights)), f.lobe[g], scale[g],
                           f.s.material, k.tr.ambient != 0);
  }
  return out;
}

// Light i's share of sum: color * att * (diffuse + lobe * T), or the ambient light plus it for
// the first light.
void accumulate_light(Fragment& f, const Key& k, const FragmentLobe& lobe, size_t i,
                      bool& started) {
  ir::Block& code = f.code;
  const Reg sum = f.sum.masked("xyz");
  const bool point = k.list[i].type == Light::Type::Point;
  Reg x = read_lane(f.diffuse, i);
  if (k.term) {
    const Reg& l = lobe.lanes[i];
    if (!lobe.scale_in_accumulation.empty()) {
      emit_scale_and_ambient(code, l.as_destination(), l, read_lane(lobe.scale_in_accumulation, i),
                             f.s.material, k.tr.ambient != 0);
    }
    const Reg acc = f.acc();
    code.op(Op::MAD, acc.masked("xyz"), {l, k.fold_scale ? f.scaled_T[i] : f.T, x});
    if (point) code.op(Op::MUL, acc.masked("xyz"), {acc, read_lane(f.att, i)});
    x = acc;
  } else if (point) {
    code.op(Op::MUL, write_lane(f.diffuse, i), {x, read_lane(f.att, i)});
  }
  if (started) {
    code.op(Op::MAD, sum, {x, f.color[i], f.sum});
  } else if (k.ambient) {
    code.op(Op::MAD, sum, {x, f.color[i], f.ambient});
  } else {
    code.op(Op::MUL, sum, {x, f.color[i]});
  }
  started = true;
}

// Group g's share of sum as dot products: for each colour channel c, DP4(att * diffuse, c of
// each light) + T * DP4(att * (lobe*s + a), c of each light) (DP3 for three lights).
void accumulate_dot(Fragment& f, const Key& k, size_t g, bool& started) {
  ir::Block& code = f.code;
  const std::string m = group_mask(g, k.lights);
  const bool point = k.list[g * 4].type == Light::Type::Point;
  const Op dp = m.size() == 4 ? Op::DP4 : Op::DP3;
  // position - P is dead by now: its x register holds the second sum.
  const Reg spare = f.d[0].valid() ? f.d[0] : f.acc();
  const std::array<Reg, 3>& c = f.colour_rows[g];
  code.text("# group " + std::to_string(g) +
            ": the colour sums as dot products with the transposed colours.\n");
  const char* channel[] = {"x", "y", "z"};
  if (point) code.op(Op::MUL, f.diffuse[g].masked(m), {f.diffuse[g], f.att[g]});
  const Reg target = started ? spare : f.sum;
  for (int ch = 0; ch < 3; ++ch) code.op(dp, target.masked(channel[ch]), {f.diffuse[g], c[ch]});
  if (started) code.op(Op::ADD, f.sum.masked("xyz"), {f.sum, spare});
  if (k.term) {
    if (point) code.op(Op::MUL, f.lobe[g].masked(m), {f.lobe[g], f.att[g]});
    const std::array<Reg, 3>& lc = k.fold_scale ? f.scaled_rows[g] : c;
    for (int ch = 0; ch < 3; ++ch) code.op(dp, spare.masked(channel[ch]), {f.lobe[g], lc[ch]});
    code.op(Op::MAD, f.sum.masked("xyz"), {spare, f.T, f.sum});
  }
  started = true;
}

// sum = ambient_light + sum over lights of color * att * (diffuse + lobe * T).
void accumulate(Fragment& f, const Key& k, const FragmentLobe& lobe) {
  ir::Block& code = f.code;
  code.text(
      "\n# sum = ambient_light + sum over lights of color * att * (diffuse + (lobe*s + a) * T).\n");
  const Reg sum = f.sum.masked("xyz");
  bool started = false;
  for (size_t g = 0; g < k.groups; ++g) {
    if (k.dot_sums[g]) {
      accumulate_dot(f, k, g, started);
      continue;
    }
    for (size_t i = g * 4; i < g * 4 + lanes_of_group(g, k.lights); ++i) {
      accumulate_light(f, k, lobe, i, started);
    }
  }
  if (k.lights == 0) {
    if (k.ambient) {
      code.op(Op::MOV, sum, {f.ambient});
    } else {
      code.op(Op::SUB, sum, {f.albedo, f.albedo}, "0");
    }
  }
}

ir::Program fragment_program(Key& k, const Material& material,
                             std::optional<model::PowerLut>& lut) {
  ir::Program p(ir::ProgramKind::Fragment);
  Fragment f(p);
  declare_fragment(f, k, material);
  f.code.text(
      "# N = n / |n|, or 0 when |n| < 1e-6 (then diffuse = 0 and H = L, as the reference).\n");
  emit_normal(f.code, f.s, attrib("fragment.texcoord[1]"));
  if (k.view_dots) {
    emit_inverse_eye_distance(f.code, f.s.P, f.s.V.swz("w"));
  } else if (k.fragment_lobe && !k.ortho && !k.packed_view_dots) {
    emit_view_vector(f.code, f.s);
  }
  fragment_lights(f, k);
  accumulate(f, k, emit_lobe(f, k, lut));
  f.code.text("\n");
  const Reg color = output("result.color");
  if (ambient_in_final(k)) {
    const Reg ambient_albedo = f.decls.param(
        "ambient_albedo", vec4(k.scene.ambient_light * material.albedo, 0), "ambient * albedo");
    f.code.op(Op::MAD, color.masked("xyz"), {f.sum, f.albedo, ambient_albedo});
  } else {
    if (ambient_after_sum(k)) f.code.op(Op::ADD, f.sum.masked("xyz"), {f.sum, f.ambient});
    f.code.op(Op::MUL, color.masked("xyz"), {f.sum, f.albedo_rgb});
  }
  f.code.op(Op::MOV, color.masked("w"), {f.albedo.swz("w")});
  // Known only now: every temporary (the LUT's) and every note (sg-fitted's).
  f.temps.text("\n");
  f.temps.temps();
  f.temps.text("\n");
  std::string head = kFragmentHeader;
  head += "# Variant: " + (k.term ? k.variant.name() : std::string("no translucency term")) + "\n";
  for (const std::string& n : k.notes) head += "# note: " + n + "\n";
  f.head.text(head + "\n");
  return p;
}

}  // namespace

namespace {

ArbPrograms generate_with(const Scene& scene, const Material& material, const PowVariant& variant,
                          bool translucency_term, const Layout& layout,
                          const LightNumbers& numbers) {
  Key k = make_key(scene, material, variant, translucency_term, layout, numbers);
  ArbPrograms out;
  out.fragment_program = fragment_program(k, material, out.lut);
  out.vertex_program = vertex_program(k);
  out.notes = k.notes;
  return out;
}

// The layouts worth trying for `lights` lights: by kind only when both kinds are there; a packing
// threshold only where it changes which groups are packed (every group but the last has four
// lights: 5 packs none, 4 the full groups, the last group's size all of them); dot sums only
// where a packed group has three or four lights. The scale fold saves one instruction per group
// wherever it applies, so it is always on.
std::vector<Layout> candidate_layouts(const Scene& scene) {
  bool point = false, directional = false;
  for (const Light& l : scene.lights) (l.type == Light::Type::Point ? point : directional) = true;
  const size_t n = scene.lights.size();
  const size_t last = n == 0 ? 0 : n - 4 * (group_count(n) - 1);
  std::vector<size_t> thresholds = {5};
  if (n >= 4) thresholds.push_back(4);
  if (last >= 2 && last < 4) thresholds.push_back(last);
  std::vector<Layout> out;
  for (bool by_kind : {false, true}) {
    if (by_kind && !(point && directional)) continue;
    for (size_t pack_min : thresholds) {
      out.push_back({by_kind, pack_min, false, true});
      if (pack_min <= 4 && (n >= 4 || last >= 3)) out.push_back({by_kind, pack_min, true, true});
    }
  }
  // The view dots apply to directional lights computed one by one, or to every light packed
  // (apply_layout decides which, or neither).
  const size_t layouts = out.size();
  for (size_t i = 0; i < layouts; ++i) {
    Layout l = out[i];
    l.view_dots = true;
    out.push_back(l);
  }
  return out;
}

// The programs of the layout with the shortest fragment program (ALU + TEX, then temporaries;
// the first of equals, so a scene packing does not shorten keeps the light-by-light program).
// Chosen on the program with the term and only the guards the scene needs, so `:guards=all`
// lays the lights out the same way and renders the same bits wherever no guard triggers
// (arb_guards_test), and the program without the term is the same program minus the term (the
// budget's term cost).
ArbPrograms generate_best(const Scene& scene, const Material& material, const PowVariant& variant,
                          bool translucency_term, const LightNumbers& numbers) {
  PowVariant chooser = variant;
  chooser.all_guards = false;
  std::optional<ArbPrograms> best;
  Layout best_layout;
  std::pair<int, int> least;
  for (const Layout& l : candidate_layouts(scene)) {
    ArbPrograms p = generate_with(scene, material, chooser, true, l, numbers);
    const budget::ProgramCounts c = ir::count(p.fragment_program);
    const std::pair<int, int> key(c.alu + c.tex, c.temporaries);
    if (best && !(key < least)) continue;
    best = std::move(p);
    best_layout = l;
    least = key;
  }
  if (variant.all_guards || !translucency_term) {
    return generate_with(scene, material, variant, translucency_term, best_layout, numbers);
  }
  return std::move(*best);
}

}  // namespace

ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         bool translucency_term, const LightNumbers& numbers) {
  ArbPrograms out = generate_best(scene, material, variant, translucency_term, numbers);
  out.vertex = ir::print(out.vertex_program);
  out.fragment = ir::print(out.fragment_program);
  return out;
}

}  // namespace lt::arbfp
