#include "paths/arbfp/arb_generator.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_guards.h"
#include "paths/arbfp/arb_lobe.h"
#include "paths/arbfp/arb_thickness_map.h"

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
#                          (then the fragment program has no t, V, H or lobe of its own)
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

// What the scene, the material and the variant ask of the two programs, decided once (Mesa's
// state key): the generators below only read it.
struct Key {
  const Scene& scene;
  const Translucency tr;  // the material's, or the defaults when it has none
  const PowVariant& variant;
  bool term = false;              // the translucency term is generated
  bool flat_lobe = false;         // p = 0: t^0 = 1 everywhere (0^0 := 1), no t and no lobe
  bool vertex_lobe = false;       // pow=mul:vertex: the vertex program computes the lobe
  bool fragment_lobe = false;     // the fragment program computes t and the lobe
  bool vertex_thickness = false;  // T comes from the vertex colour
  bool map_thickness = false;     // T comes from a thickness map (arb_thickness_map.h)
  bool ortho = false, ambient = false, any_point = false;
  size_t lights = 0, groups = 0;
  PowMethod method = PowMethod::Exact;  // the variant's, after pow=mul's fallback
  GuardNeeds guards = {};               // the fragment program's, for this scene
  std::vector<std::string> notes = {};
};

Key make_key(const Scene& scene, const Material& material, const PowVariant& variant,
             bool translucency_term) {
  Key k{scene, material.translucency.value_or(Translucency{}), variant};
  k.term = translucency_term && material.translucency.has_value();
  k.lights = scene.lights.size();
  k.groups = group_count(k.lights);
  k.vertex_thickness = k.term && k.tr.thickness_source == ThicknessSource::Vertex;
  k.map_thickness = k.term && k.tr.thickness_source == ThicknessSource::Texture;
  k.ortho = scene.camera.projection == Camera::Projection::Orthographic;
  k.ambient = scene.ambient_light != glm::dvec3(0);
  k.flat_lobe = k.term && k.tr.power == 0;
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
  if (k.term && !k.flat_lobe && k.method == PowMethod::Mul && !is_integer_power(k.tr.power)) {
    k.notes.push_back(variant.name() + ": power " + ir::num(k.tr.power) +
                      " is not an integer, exact POW used instead" +
                      (variant.per_vertex ? " (per vertex)" : ""));
    k.method = PowMethod::Exact;
  }
  if (k.flat_lobe) k.notes.push_back("power 0: the lobe is 1 everywhere (0^0 := 1), no pow");
  k.guards = guard_needs(scene, material, variant.all_guards);
  for (const std::string& n : k.guards.notes) k.notes.push_back(n);
  if (k.vertex_lobe) {
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
// this variant's error.
void emit_vertex_lobe(ir::Program& p, Key& k) {
  ir::Block decls = p.block(), temps = p.block(), code = p.block();
  decls.text(
      "# The translucency lobe per vertex (pow=mul:vertex): the fragment program only adds\n"
      "# lobe * T to the diffuse term of each light.\n");
  Shading s;
  s.P = attrib("vertex.position");
  s.material = declare_material(decls, k.tr);
  s.guard = declare_guards(decls);
  if (k.ortho) s.V = declare_orthographic_view(decls, k.scene);
  std::vector<Reg> light_vector, scale;
  for (size_t i = 0; i < k.lights; ++i) {
    light_vector.push_back(declare_light_vector(decls, k.scene, i));
  }
  for (size_t g = 0; g < k.groups; ++g) scale.push_back(declare_scale(decls, k.scene, g));

  s.r = p.temp("r");
  s.N = p.temp("N");
  s.H = p.temp("H");
  if (!k.ortho) s.V = p.temp("V");
  if (k.any_point) s.L = p.temp("L");
  std::vector<Reg> tv, lobe;
  for (size_t g = 0; g < k.groups; ++g) {
    tv.push_back(p.temp("tv" + std::to_string(g)));
    lobe.push_back(p.temp("lobe" + std::to_string(g)));
  }
  temps.temps();

  code.text("# N = n / |n|, or 0 when |n| < 1e-6 (then H = L, as the reference).\n");
  emit_normal(code, s, attrib("vertex.normal"));
  if (!k.ortho) emit_view_vector(code, s);
  for (size_t i = 0; i < k.lights; ++i) {
    const Reg L = emit_light_direction(code, s, k.scene, i, light_vector[i]);
    emit_t(code, s, L, k.tr.normalize_distorted_light, write_lane(tv, i));
  }
  code.text("# t = saturate(dot(V, -H)) for a whole group at once (no _SAT in vertex programs).\n");
  for (size_t g = 0; g < k.groups; ++g) {
    const Reg dst = tv[g].masked(group_mask(g, k.lights));
    code.op(Op::MAX, dst, {tv[g], s.material.zero});
    code.op(Op::MIN, dst, {tv[g], s.guard.one});
  }
  LobeInput in{decls, code, s, k.variant, k.tr, k.lights, tv, lobe, k.any_point, k.notes};
  lobe_mul_vertex(in, k.method);
  code.text("# lobe * s + a, to the fragment program.\n");
  for (size_t g = 0; g < k.groups; ++g) {
    const Reg out = output("result.texcoord[" + std::to_string(kVertexLobeTexcoord + g) + "]");
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
  if (k.vertex_thickness) {
    // T = vertex colour * tint is multiplied here: the tint is constant, so interpolating the
    // product equals the product of the interpolation, and the fragment program saves one MUL
    // per pixel.
    b.text("# Vertex thickness: the mesh colour times the material's tint.\n");
    const Reg tint = b.param("tint", vec4(k.tr.tint, 0));
    b.op(Op::MUL, output("result.texcoord[2]"), {attrib("vertex.color"), tint});
  } else if (k.map_thickness) {
    emit_map_uv(b);
  } else {
    b.text("# (constant thickness: nothing more to pass)\n");
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
  Reg albedo, sum, acc, T, ambient;
  std::vector<Reg> diffuse, tv, lobe, att;        // per group
  std::vector<Reg> color, light_vector, light_k;  // per light
};

// Declarations in print order (the TEMP statement lists the temporaries in allocation order).
void declare_fragment(Fragment& f, const Key& k, const Material& material) {
  ir::Program& p = f.p;
  ir::Block& d = f.decls;
  d.text("# albedo.w = 1 is the output alpha (coverage for the comparison).\n");
  f.albedo = d.param("albedo", vec4(material.albedo, 1));
  f.s.guard = declare_guards(d);
  f.s.zero_normal_guard = k.guards.zero_normal;
  f.s.P = attrib("fragment.texcoord[0]");
  f.s.r = p.temp("r");
  f.s.N = p.temp("N");
  f.sum = p.temp("sum");
  if (k.fragment_lobe) f.s.H = p.temp("H");
  if (k.any_point) f.s.L = p.temp("L");
  for (size_t g = 0; g < k.groups; ++g) {
    const std::string n = std::to_string(g);
    f.diffuse.push_back(p.temp("diffuse" + n));
    if (k.fragment_lobe) f.tv.push_back(p.temp("tv" + n)), f.lobe.push_back(p.temp("lobe" + n));
    if (k.any_point) f.att.push_back(p.temp("att" + n));
  }
  if (k.term) {
    f.acc = p.temp("acc");
    if (k.vertex_lobe) {
      d.text("# pow=mul:vertex: (lobe * s + a) of light group g comes in fragment.texcoord[" +
             std::to_string(kVertexLobeTexcoord) + " + g]\n");
    } else {
      f.s.material = declare_material(d, k.tr);
    }
    if (k.vertex_thickness) {
      // The vertex program multiplied the tint in (see there).
      d.text("# T = fragment.texcoord[2]: vertex colour * tint\n");
      f.T = attrib("fragment.texcoord[2]");
    } else if (k.map_thickness) {
      f.T = emit_map_thickness(p, d, f.code, k.tr.tint);
    } else {
      d.text("# constant thickness * tint\n");
      f.T = d.param("T", vec4(k.tr.thickness * k.tr.tint, 0));
    }
    if (k.fragment_lobe) f.s.V = k.ortho ? declare_orthographic_view(d, k.scene) : p.temp("V");
  }
  if (k.ambient) f.ambient = d.param("ambient_light", vec4(k.scene.ambient_light, 0));
  for (size_t i = 0; i < k.lights; ++i) {
    const Light& l = k.scene.lights[i];
    const std::string prefix = "light" + std::to_string(i) + "_";
    f.color.push_back(d.param(prefix + "color", vec4(l.color, 0)));
    f.light_vector.push_back(declare_light_vector(d, k.scene, i));
    f.light_k.push_back(l.type == Light::Type::Point
                            ? d.param(prefix + "k", ir::vec4(l.kc, l.kl, l.kq, 0), "kc, kl, kq")
                            : Reg{});
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

// Per light: diffuse (and attenuation), then t.
void fragment_lights(Fragment& f, const Key& k) {
  ir::Block& code = f.code;
  code.text(
      "\n# Per light: diffuse (and attenuation), then t = saturate(dot(V, -H)) with H = L + "
      "N*d.\n");
  for (size_t i = 0; i < k.lights; ++i) {
    const Reg L =
        emit_light_direction(code, f.s, k.scene, i, f.light_vector[i], k.guards.distance_zero[i]);
    if (k.scene.lights[i].type == Light::Type::Point) {
      emit_attenuation(code, f.s, f.light_k[i], write_lane(f.att, i),
                       k.guards.attenuation_floor[i]);
    }
    code.op_sat(Op::DP3, write_lane(f.diffuse, i), {f.s.N, L});
    if (k.fragment_lobe) emit_t(code, f.s, L, k.tr.normalize_distorted_light, write_lane(f.tv, i));
  }
}

// Each light's lobe as the accumulation reads it.
struct FragmentLobe {
  LobeLanes lanes;
  // The LUT's lanes hold t^p and are scaled light by light in the accumulation (these are the
  // scales, per group); every other lobe arrives as lobe * s + a (empty).
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

// The lobe t^p for every light, by the variant's method, then lobe * s + a per group.
FragmentLobe emit_lobe(Fragment& f, Key& k, std::optional<model::PowerLut>& lut) {
  f.code.text("\n# The lobe t^p for every light of a group at once, then (lobe * s + a).\n");
  FragmentLobe out;
  LobeLanes& lanes = out.lanes;
  if (k.vertex_lobe) {
    f.code.text("# pow=mul:vertex: the lobe, times s plus a, was computed per vertex.\n");
    for (size_t i = 0; i < k.lights; ++i) {
      const std::string texcoord = std::to_string(kVertexLobeTexcoord + i / 4);
      lanes.push_back(attrib("fragment.texcoord[" + texcoord + "]").swz(component(i)));
    }
    return out;
  }
  if (!k.term) return out;
  if (k.flat_lobe) {
    for (size_t g = 0; g < k.groups; ++g) {
      const std::array<double, 4> s = light_scales(k.scene, g);
      const double a = k.tr.ambient;
      f.lobe.push_back(f.decls.param("lobe" + std::to_string(g),
                                     ir::vec4(s[0] + a, s[1] + a, s[2] + a, s[3] + a),
                                     "1 * s + a (flat lobe)"));
    }
    for (size_t i = 0; i < k.lights; ++i) lanes.push_back(read_lane(f.lobe, i));
    return out;
  }
  LobeInput in{f.decls, f.code, f.s, k.variant, k.tr, k.lights, f.tv, f.lobe, k.any_point, k.notes};
  if (k.method == PowMethod::Lut) {
    lut = model::PowerLut::build(k.variant.lut_size, k.variant.lut_format, {k.tr.power});
  }
  lanes = fragment_method(in, k.method, lut ? &*lut : nullptr);
  std::vector<Reg> scale;
  for (size_t g = 0; g < k.groups; ++g) scale.push_back(declare_scale(f.decls, k.scene, g));
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

// sum = ambient_light + sum over lights of color * att * (diffuse + lobe * T).
void accumulate(Fragment& f, const Key& k, const FragmentLobe& lobe) {
  ir::Block& code = f.code;
  code.text(
      "\n# sum = ambient_light + sum over lights of color * att * (diffuse + (lobe*s + a) * T).\n");
  const Reg sum = f.sum.masked("xyz");
  for (size_t i = 0; i < k.lights; ++i) {
    const bool point = k.scene.lights[i].type == Light::Type::Point;
    Reg x = read_lane(f.diffuse, i);
    if (k.term) {
      const Reg& l = lobe.lanes[i];
      if (!lobe.scale_in_accumulation.empty()) {
        emit_scale_and_ambient(code, l.as_destination(), l,
                               read_lane(lobe.scale_in_accumulation, i), f.s.material,
                               k.tr.ambient != 0);
      }
      code.op(Op::MAD, f.acc.masked("xyz"), {l, f.T, x});
      if (point) code.op(Op::MUL, f.acc.masked("xyz"), {f.acc, read_lane(f.att, i)});
      x = f.acc;
    } else if (point) {
      code.op(Op::MUL, write_lane(f.diffuse, i), {x, read_lane(f.att, i)});
    }
    if (i > 0) {
      code.op(Op::MAD, sum, {x, f.color[i], f.sum});
    } else if (k.ambient) {
      code.op(Op::MAD, sum, {x, f.color[i], f.ambient});
    } else {
      code.op(Op::MUL, sum, {x, f.color[i]});
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
  if (k.fragment_lobe && !k.ortho) emit_view_vector(f.code, f.s);
  fragment_lights(f, k);
  accumulate(f, k, emit_lobe(f, k, lut));
  f.code.text("\n");
  f.code.op(Op::MUL, output("result.color").masked("xyz"), {f.sum, f.albedo});
  f.code.op(Op::MOV, output("result.color").masked("w"), {f.albedo.swz("w")});
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

ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         bool translucency_term) {
  Key k = make_key(scene, material, variant, translucency_term);
  ArbPrograms out;
  out.fragment_program = fragment_program(k, material, out.lut);
  out.vertex_program = vertex_program(k);
  out.vertex = ir::print(out.vertex_program);
  out.fragment = ir::print(out.fragment_program);
  out.notes = k.notes;
  return out;
}

}  // namespace lt::arbfp
