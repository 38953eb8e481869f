#include "paths/arbfp/arb_fragment_program.h"

#include "paths/arbfp/arb_albedo_map.h"
#include "paths/arbfp/arb_guards.h"
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

// The program's own description, at their top (what `ltrender info --source` shows).
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
FragmentLobe emit_lobe(Fragment& f, const Key& k, std::optional<model::PowerLut>& lut,
                       std::vector<std::string>& notes) {
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
  LobeInput in{f.decls, f.code, f.s,   k.variant, k.tr,           k.lights,
               f.tv,    f.lobe, notes, {},        lobe_scratch(f)};
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

}  // namespace

ir::Program fragment_program(const Key& k, const Material& material,
                             std::optional<model::PowerLut>& lut, std::vector<std::string>& notes) {
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
  accumulate(f, k, emit_lobe(f, k, lut, notes));
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
  for (const std::string& n : notes) head += "# note: " + n + "\n";
  f.head.text(head + "\n");
  return p;
}

}  // namespace lt::arbfp
