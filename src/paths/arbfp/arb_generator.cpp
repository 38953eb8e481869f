#include "paths/arbfp/arb_generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "gl/program.h"
#include "model/pow_curves.h"
#include "model/translucency.h"

namespace lt::arbfp {

namespace {

// ARB programs take float literals; %.9g round-trips a float exactly.
std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", static_cast<double>(static_cast<float>(v)));
  return buf;
}

std::string vec4(double x, double y, double z, double w) {
  std::string s = "{";
  s.append(num(x)).append(", ").append(num(y)).append(", ").append(num(z)).append(", ");
  s.append(num(w)).append("}");
  return s;
}
std::string vec4(const glm::dvec3& v, double w) {
  return vec4(v.x, v.y, v.z, w);
}

bool is_integer_power(double p) {
  return p >= 1 && p == std::floor(p) && p <= 1 << 20;
}

const char kComponents[] = "xyzw";

}  // namespace

namespace {

// One light's place in the packed registers: group g (diffuse<g>, tv<g>, lobe<g>, att<g>) and
// component c.
struct Slot {
  std::string g, c;
};
Slot slot(size_t i) {
  return {std::to_string(i / 4), std::string(1, kComponents[i % 4])};
}
// Write mask covering the lights of group g.
std::string group_mask(size_t g, size_t lights) {
  const size_t n = std::min<size_t>(4, lights - g * 4);
  std::string mask = ".";
  mask.append(kComponents, n);
  return mask;
}

// t^k from tv<g> into lobe<g> for every group, by left-to-right binary exponentiation: one MUL per
// bit after the leading one, plus one per set bit; no extra register (t stays in tv<g>). Both
// program kinds have MUL and MOV, so the fragment program and pow=mul:vertex's vertex program
// share it.
void emit_mul_chain(std::ostream& out, unsigned long k, size_t groups, size_t n_lights) {
  int top = 0;
  while ((k >> (top + 1)) != 0) ++top;
  for (size_t g = 0; g < groups; ++g) {
    const std::string lg = "lobe" + std::to_string(g), tg = "tv" + std::to_string(g);
    const std::string m = group_mask(g, n_lights);
    std::string cur = tg;
    for (int b = top - 1; b >= 0; --b) {
      out << "MUL " << lg << m << ", " << cur << ", " << cur << ";\n";
      cur = lg;
      if ((k >> b) & 1) out << "MUL " << lg << m << ", " << lg << ", " << tg << ";\n";
    }
    if (cur == tg) out << "MOV " << lg << m << ", " << tg << ";  # p = 1\n";
  }
}

// The group's light scales s, packed like the lights.
std::string scale_param(const Scene& scene, size_t g) {
  double s[4] = {0, 0, 0, 0};
  for (size_t i = g * 4; i < std::min(scene.lights.size(), g * 4 + 4); ++i) {
    s[i % 4] = scene.lights[i].translucency_scale;
  }
  return "PARAM scale" + std::to_string(g) + " = " + vec4(s[0], s[1], s[2], s[3]) +
         ";  # s per light\n";
}

// pow=mul:vertex, the vertex program's part: N, V, L, H, t = saturate(dot(V, -H)), the lobe t^p
// and (lobe * s + a) per vertex, into texcoord[kVertexLobeTexcoord + g] (lobe * s + a is linear
// in the lobe, so interpolating it equals applying it to the interpolated lobe). Written with
// ARB_vertex_program's instructions only: no CMP and no _SAT there, so the hard cases select with
// SGE/SLT masks and saturate is MAX/MIN. Every hard-case convention of src/model/translucency.h
// holds at the vertices; between them the lobe is Gouraud-interpolated (also for point lights,
// whose L is taken at the vertex here, like the combiners path), which is this variant's error.
std::string vertex_lobe_block(const Scene& scene, const Translucency& tr, PowMethod method) {
  const size_t n_lights = scene.lights.size();
  const size_t groups = (n_lights + 3) / 4;
  const bool ortho = scene.camera.projection == Camera::Projection::Orthographic;
  bool any_point = false;
  for (const Light& l : scene.lights) any_point |= l.type == Light::Type::Point;
  std::ostringstream params, code;
  std::string temps = "r, N, H";
  if (!ortho) temps += ", V";
  if (any_point) temps += ", L";
  for (size_t g = 0; g < groups; ++g)
    temps += ", tv" + std::to_string(g) + ", lobe" + std::to_string(g);

  params << "# The translucency lobe per vertex (pow=mul:vertex): the fragment program only adds\n"
         << "# lobe * T to the diffuse term of each light.\n"
         << "# material = (distortion d, power p, lt ambient a, 0)\n"
         << "PARAM material = " << vec4(tr.distortion, tr.power, tr.ambient, 0) << ";\n"
         << "# guard = the fragment program's (x, y: zero normal; w: 1/|v| clamp so 0 * 1e30 = 0\n"
         << "# where IEEE would give 0 * inf = NaN); z = 1, the upper bound of saturate.\n"
         << "PARAM guard = {1e6, 1e-12, 1, 1e30};\n";
  if (ortho) {
    params << "# orthographic: every view ray is parallel, V = -forward\n"
           << "PARAM V = " << vec4(-scene.camera.forward(), 0) << ";\n";
  }
  for (size_t i = 0; i < n_lights; ++i) {
    const Light& l = scene.lights[i];
    const std::string li = "light" + std::to_string(i) + "_";
    if (l.type == Light::Type::Directional) {
      params << "PARAM " << li << "L = " << vec4(-l.direction, 0) << ";  # -direction\n";
    } else {
      params << "PARAM " << li << "position = " << vec4(l.position - scene.camera.eye, 0)
             << ";  # camera-relative\n";
    }
  }
  for (size_t g = 0; g < groups; ++g) params << scale_param(scene, g);

  code << "# N = n / |n|, or 0 when |n| < 1e-6 (then H = L, as the reference).\n"
       << "DP3 r.x, vertex.normal, vertex.normal;\n"
       << "RSQ r.y, r.x;\n"
       << "MIN r.y, r.y, guard.x;\n"
       << "SGE r.z, r.x, guard.y;\n"
       << "MUL r.y, r.y, r.z;\n"
       << "MUL N.xyz, vertex.normal, r.y;\n";
  if (!ortho) {
    // No rasterised point is at the eye (near > 0), but a clipped triangle's vertex can be: there
    // V = 0 (t = 0) instead of 0 * inf.
    code << "# V = normalize(-P), 0 for a vertex at the eye (1/|P| clamped to 1e30).\n"
         << "DP3 V.w, vertex.position, vertex.position;\n"
         << "RSQ V.w, V.w;\n"
         << "MIN V.w, V.w, guard.w;\n"
         << "MUL V.xyz, -vertex.position, V.w;\n";
  }
  for (size_t i = 0; i < n_lights; ++i) {
    const Light& l = scene.lights[i];
    const std::string li = "light" + std::to_string(i) + "_";
    const Slot sl = slot(i);
    std::string L = "L";
    if (l.type == Light::Type::Directional) {
      L = li + "L";
      code << "# light " << i << ": directional\n";
    } else {
      code << "# light " << i << ": point, L at the vertex. L = (position - P) / dist, and L = N "
           << "at distance 0:\n# there 0 * min(RSQ(0), 1e30) = 0, and the SGE mask adds N.\n"
           << "SUB L.xyz, " << li << "position, vertex.position;\n"
           << "DP3 L.w, L, L;\n"
           << "RSQ r.x, L.w;\n"
           << "MIN r.x, r.x, guard.w;\n"
           << "MUL L.xyz, L, r.x;\n"
           << "SGE r.y, -L.w, material.w;\n"
           << "MAD L.xyz, N, r.y, L;\n";
    }
    code << "MAD H.xyz, N, material.x, " << L << ";\n";
    if (tr.normalize_distorted_light) {
      code << "# normalised H on request: normalize(0) := 0 (1/|H| clamped to 1e30).\n"
           << "DP3 H.w, H, H;\n"
           << "RSQ H.w, H.w;\n"
           << "MIN H.w, H.w, guard.w;\n"
           << "MUL H.xyz, H, H.w;\n";
    }
    code << "DP3 tv" << sl.g << "." << sl.c << ", V, -H;\n";
  }
  code << "# t = saturate(dot(V, -H)) for a whole group at once (no _SAT in vertex programs).\n";
  for (size_t g = 0; g < groups; ++g) {
    const std::string m = group_mask(g, n_lights);
    code << "MAX tv" << g << m << ", tv" << g << ", material.w;\n"
         << "MIN tv" << g << m << ", tv" << g << ", guard.z;\n";
  }
  if (method == PowMethod::Mul) {
    const auto k = static_cast<unsigned long>(tr.power);
    code << "# t^" << k << " by repeated squaring (exact up to float rounding).\n";
    emit_mul_chain(code, k, groups, n_lights);
  } else {
    // POW is EX2(p * LG2(t)) and LG2(0) = -inf: POW reads t clamped to the smallest normal float
    // (finite everywhere), and the (t > 0) mask makes the model's 0 for t = 0 (0^p, p > 0; p = 0
    // never gets here: flat lobe).
    params << "PARAM pow_floor = " << vec4(std::ldexp(1.0, -126), 0, 0, 0) << ";  # 2^-126\n";
    code << "# non-integer p: POW of max(t, 2^-126), times (t > 0) for the model's 0^p = 0.\n";
    for (size_t i = 0; i < n_lights; ++i) {
      const Slot sl = slot(i);
      code << "MAX r.x, tv" << sl.g << "." << sl.c << ", pow_floor.x;\n"
           << "POW lobe" << sl.g << "." << sl.c << ", r.x, material.y;\n";
    }
    for (size_t g = 0; g < groups; ++g) {
      const std::string m = group_mask(g, n_lights);
      code << "SLT r" << m << ", material.w, tv" << g << ";\n"
           << "MUL lobe" << g << m << ", lobe" << g << ", r;\n";
    }
  }
  code << "# lobe * s + a, to the fragment program.\n";
  for (size_t g = 0; g < groups; ++g) {
    const std::string m = group_mask(g, n_lights);
    const std::string out = "result.texcoord[" + std::to_string(kVertexLobeTexcoord + g) + "]";
    if (tr.ambient != 0) {
      code << "MAD " << out << m << ", lobe" << g << ", scale" << g << ", material.z;\n";
    } else {
      code << "MUL " << out << m << ", lobe" << g << ", scale" << g << ";  # a = 0\n";
    }
  }
  return params.str() + "TEMP " + temps + ";\n" + code.str();
}

}  // namespace

ArbPrograms generate_arb(const Scene& scene, const Material& material, const PowVariant& variant,
                         bool translucency_term) {
  ArbPrograms out;
  const bool term = translucency_term && material.translucency.has_value();
  const Translucency tr = material.translucency.value_or(Translucency{});
  const size_t n_lights = scene.lights.size();
  const size_t groups = (n_lights + 3) / 4;
  const bool vertex_thickness = term && tr.thickness_source == ThicknessSource::Vertex;
  const bool ortho = scene.camera.projection == Camera::Projection::Orthographic;
  const bool ambient = scene.ambient_light != glm::dvec3(0);
  // p = 0: t^0 = 1 everywhere (0^0 := 1), so the lobe and t are not computed at all.
  const bool flat_lobe = term && tr.power == 0;
  bool any_point = false;
  for (const Light& l : scene.lights) any_point |= l.type == Light::Type::Point;
  // pow=mul:vertex: the vertex program computes the lobe; the fragment program reads it.
  const bool vertex_lobe = term && !flat_lobe && variant.per_vertex;
  // The fragment program's own t and lobe.
  const bool fragment_lobe = term && !flat_lobe && !vertex_lobe;
  if (vertex_lobe && n_lights > kMaxVertexLobeLights) {
    throw InputError("--variant", variant.name(),
                     "the per-vertex lobe takes at most " + std::to_string(kMaxVertexLobeLights) +
                         " lights (four per texcoord, texcoord[3..7]); the scene has " +
                         std::to_string(n_lights));
  }

  PowMethod method = variant.method;
  if (term && !flat_lobe && method == PowMethod::Mul && !is_integer_power(tr.power)) {
    out.notes.push_back(variant.name() + ": power " + num(tr.power) +
                        " is not an integer, exact POW used instead" +
                        (variant.per_vertex ? " (per vertex)" : ""));
    method = PowMethod::Exact;
  }
  if (flat_lobe) out.notes.push_back("power 0: the lobe is 1 everywhere (0^0 := 1), no pow");
  if (vertex_lobe) {
    out.notes.push_back(std::string("pow=mul:vertex: t and the lobe per vertex, Gouraud-") +
                        "interpolated" + (any_point ? " (point lights: L at the vertex too)" : ""));
  }

  std::ostringstream params, view, lights, lobe, acc;
  std::vector<std::string> temps = {"r", "N", "sum"};
  if (fragment_lobe) temps.push_back("H");
  if (any_point) temps.push_back("L");
  for (size_t g = 0; g < groups; ++g) {
    const std::string s = std::to_string(g);
    temps.push_back("diffuse" + s);
    if (fragment_lobe) temps.push_back("tv" + s), temps.push_back("lobe" + s);
    if (any_point) temps.push_back("att" + s);
  }
  if (term) temps.push_back("acc");

  // Constants: material, view, thickness, lobe parameters.
  if (term) {
    if (vertex_lobe) {
      params << "# pow=mul:vertex: (lobe * s + a) of light group g comes in fragment.texcoord["
             << kVertexLobeTexcoord << " + g]\n";
    } else {
      params << "# material = (distortion d, power p, lt ambient a, 0)\n"
             << "PARAM material = " << vec4(tr.distortion, tr.power, tr.ambient, 0) << ";\n";
    }
    if (vertex_thickness) {
      // T = vertex colour * tint is multiplied in the vertex program: the tint is constant, so
      // interpolating the product equals the product of the interpolation, and the fragment
      // program saves one MUL per pixel.
      params << "# T = fragment.texcoord[2]: vertex colour * tint\n";
    } else {
      params << "# constant thickness * tint\n"
             << "PARAM T = " << vec4(tr.thickness * tr.tint, 0) << ";\n";
    }
    if (fragment_lobe) {
      if (ortho) {
        params << "# orthographic: every view ray is parallel, V = -forward\n"
               << "PARAM V = " << vec4(-scene.camera.forward(), 0) << ";\n";
      } else {
        temps.push_back("V");
        view << "# V = normalize(-P): the eye is the origin of camera-relative space.\n"
             << "DP3 V.w, fragment.texcoord[0], fragment.texcoord[0];\n"
             << "RSQ V.w, V.w;\n"
             << "MUL V.xyz, -fragment.texcoord[0], V.w;\n";
      }
    }
  }
  if (ambient) params << "PARAM ambient_light = " << vec4(scene.ambient_light, 0) << ";\n";

  // Per light: diffuse, attenuation, t.
  for (size_t i = 0; i < n_lights; ++i) {
    const Light& l = scene.lights[i];
    const std::string li = "light" + std::to_string(i) + "_";
    const Slot sl = slot(i);
    params << "PARAM " << li << "color = " << vec4(l.color, 0) << ";\n";
    std::string L = "L";
    if (l.type == Light::Type::Directional) {
      L = li + "L";
      params << "PARAM " << li << "L = " << vec4(-l.direction, 0) << ";  # -direction\n";
      lights << "# light " << i << ": directional\n";
    } else {
      params << "PARAM " << li << "position = " << vec4(l.position - scene.camera.eye, 0)
             << ";  # camera-relative\n"
             << "PARAM " << li << "k = " << vec4(l.kc, l.kl, l.kq, 0) << ";  # kc, kl, kq\n";
      lights << "# light " << i << ": point. L = (position - P) / dist, and L = N at distance 0.\n"
             << "SUB L.xyz, " << li << "position, fragment.texcoord[0];\n"
             << "DP3 L.w, L, L;\n"
             << "RSQ r.x, L.w;\n"
             << "MUL L.xyz, L, r.x;\n"
             << "# dist^2 = 0 made L = 0 * inf = NaN above: CMP selects N instead (-dist^2 < 0 is "
                "false).\n"
             << "CMP L.xyz, -L.w, L, N;\n"
             << "# dist = 1 / RSQ(dist^2): RCP(+inf) = 0, so no NaN at distance 0.\n"
             << "RCP r.y, r.x;\n"
             << "MAD r.z, r.y, " << li << "k.y, " << li << "k.x;\n"
             << "MAD r.z, L.w, " << li << "k.z, r.z;\n"
             << "MAX r.z, r.z, guard.z;\n"
             << "RCP att" << sl.g << "." << sl.c << ", r.z;\n";
    }
    lights << "DP3_SAT diffuse" << sl.g << "." << sl.c << ", N, " << L << ";\n";
    if (fragment_lobe) {
      lights << "MAD H.xyz, N, material.x, " << L << ";\n";
      if (tr.normalize_distorted_light) {
        lights << "# normalised H on request: normalize(0) := 0 (1/|H| clamped to 1e30).\n"
               << "DP3 H.w, H, H;\n"
               << "RSQ H.w, H.w;\n"
               << "MIN H.w, H.w, guard.w;\n"
               << "MUL H.xyz, H, H.w;\n";
      }
      lights << "DP3_SAT tv" << sl.g << "." << sl.c << ", V, -H;\n";
    }
  }

  // The lobe, per group of four lights; lobe<g> ends up holding (lobe * s + a). lobe_reg[i] is
  // where light i's lobe is (the LUT variants keep one register per light, see there).
  std::vector<std::string> lobe_reg(n_lights);
  for (size_t i = 0; i < n_lights; ++i) {
    if (vertex_lobe) {
      lobe_reg[i] =
          "fragment.texcoord[" + std::to_string(kVertexLobeTexcoord + i / 4) + "]." + slot(i).c;
    } else {
      lobe_reg[i].append("lobe").append(slot(i).g).append(".").append(slot(i).c);
    }
  }
  if (vertex_lobe) {
    lobe << "# pow=mul:vertex: the lobe, times s plus a, was computed per vertex.\n";
  } else if (term) {
    // The LUT's coordinate remaps of every group come before every TEX: a TEX reading a
    // register an ALU instruction wrote starts a new texture indirection (ARB_fragment_program
    // issue 24), so this order keeps the program at 2 indirections for any light count.
    if (!flat_lobe && method == PowMethod::Lut) {
      out.lut = model::PowerLut::build(variant.lut_size, variant.lut_format, {tr.power});
      params << "# texel-centre addressing (src/model/power_lut.h): u = t * (N-1)/N + 0.5/N\n"
             << "PARAM lut = "
             << vec4(out.lut->coordinate(1) - out.lut->coordinate(0), out.lut->coordinate(0), 0, 0)
             << ";\n";
      lobe << "# " << variant.name() << ": t^p from a " << variant.lut_size
           << "-texel 1D texture, linear filtering.\n";
      for (size_t g = 0; g < groups; ++g) {
        lobe << "MAD tv" << g << group_mask(g, n_lights) << ", tv" << g << ", lut.x, lut.y;\n";
      }
      // Each TEX writes a whole register of its own: Mesa's ARB_fragment_program (llvmpipe)
      // returns wrong values from the third write-masked TEX into one register (measured: a
      // packed lobe0.z was garbage), and a TEX overwriting a register an ALU instruction read
      // since the last TEX would add an indirection. Registers dead by now are reused first.
      std::vector<std::string> pool;
      for (size_t g = 0; g < groups; ++g) pool.push_back("lobe" + std::to_string(g));
      pool.push_back("H");
      pool.push_back("r");
      if (any_point) pool.push_back("L");
      for (size_t i = 0; i < n_lights; ++i) {
        if (i >= pool.size()) {
          pool.push_back("tex" + std::to_string(i));
          temps.push_back(pool.back());
        }
        const Slot sl = slot(i);
        lobe_reg[i] = pool[i] + ".x";
        lobe << "TEX " << pool[i] << ", tv" << sl.g << "." << sl.c << ", texture[0], 1D;\n";
      }
    }
    if (!flat_lobe && (method == PowMethod::Sg || method == PowMethod::SgSimplified ||
                       method == PowMethod::SgFitted)) {
      double n = model::sg_exponent(tr.power);
      if (method == PowMethod::SgSimplified) n = tr.power;
      if (method == PowMethod::SgFitted) {
        n = model::fit_sg_exponent(tr.power);
        out.notes.push_back("pow=sg-fitted: n' = " + num(n) + " for p = " + num(tr.power) +
                            " (sg: " + num(model::sg_exponent(tr.power)) + ")");
      }
      params << "PARAM sg = " << vec4(n, 0, 0, 0) << ";  # n'\n";
      lobe << "# " << variant.name() << ": t^p ~ exp2(n' * (t - 1)) = exp2(t * n' - n'). t <= 1, "
           << "so EX2 never overflows.\n";
      for (size_t g = 0; g < groups; ++g) {
        lobe << "MAD lobe" << g << group_mask(g, n_lights) << ", tv" << g << ", sg.x, -sg.x;\n";
      }
      for (size_t i = 0; i < n_lights; ++i) {
        const Slot sl = slot(i);
        lobe << "EX2 lobe" << sl.g << "." << sl.c << ", lobe" << sl.g << "." << sl.c << ";\n";
      }
    }
    if (!flat_lobe && method == PowMethod::Mul) {
      const auto k = static_cast<unsigned long>(tr.power);
      lobe << "# pow=mul: t^" << k << " by repeated squaring (exact up to float rounding).\n";
      emit_mul_chain(lobe, k, groups, n_lights);
    }
    if (!flat_lobe && method == PowMethod::Exact) {
      lobe << "# pow=exact: POW is EX2(p * LG2(t)) and LG2(0) = -inf, so t = 0 is selected to the\n"
           << "# model's 0 by CMP (-t < 0 only when t > 0); p = 0 never gets here (flat lobe).\n";
      for (size_t i = 0; i < n_lights; ++i) {
        const Slot sl = slot(i);
        lobe << "POW lobe" << sl.g << "." << sl.c << ", tv" << sl.g << "." << sl.c
             << ", material.y;\n";
      }
      for (size_t g = 0; g < groups; ++g) {
        lobe << "CMP lobe" << g << group_mask(g, n_lights) << ", -tv" << g << ", lobe" << g
             << ", material.w;\n";
      }
    }
    // lobe * s + a, with the group's light scales packed like the lights.
    for (size_t g = 0; g < groups; ++g) {
      double s[4] = {0, 0, 0, 0};
      for (size_t i = g * 4; i < std::min(n_lights, g * 4 + 4); ++i) {
        s[i % 4] = scene.lights[i].translucency_scale;
      }
      const std::string m = group_mask(g, n_lights);
      if (flat_lobe) {
        params << "PARAM lobe" << g << " = "
               << vec4(s[0] + tr.ambient, s[1] + tr.ambient, s[2] + tr.ambient, s[3] + tr.ambient)
               << ";  # 1 * s + a (flat lobe)\n";
        continue;
      }
      params << scale_param(scene, g);
      if (method == PowMethod::Lut) continue;  // per light, in the accumulation below
      if (tr.ambient != 0) {
        lobe << "MAD lobe" << g << m << ", lobe" << g << ", scale" << g << ", material.z;\n";
      } else {
        lobe << "MUL lobe" << g << m << ", lobe" << g << ", scale" << g << ";  # a = 0\n";
      }
    }
  }

  // Accumulate: sum = ambient_light + sum_i color_i * att_i * (diffuse_i + lobe_i * T).
  for (size_t i = 0; i < n_lights; ++i) {
    const Light& l = scene.lights[i];
    const Slot sl = slot(i);
    const std::string li = "light" + std::to_string(i) + "_";
    const bool point = l.type == Light::Type::Point;
    std::string x;
    if (term) {
      if (fragment_lobe && method == PowMethod::Lut) {
        const std::string& lr = lobe_reg[i];
        acc << (tr.ambient != 0 ? "MAD " : "MUL ") << lr << ", " << lr << ", scale" << sl.g << "."
            << sl.c << (tr.ambient != 0 ? ", material.z;\n" : ";  # a = 0\n");
      }
      acc << "MAD acc.xyz, " << lobe_reg[i] << ", "
          << (vertex_thickness ? "fragment.texcoord[2]" : "T") << ", diffuse" << sl.g << "." << sl.c
          << ";\n";
      if (point) acc << "MUL acc.xyz, acc, att" << sl.g << "." << sl.c << ";\n";
      x = "acc";
    } else {
      x = "diffuse" + sl.g + "." + sl.c;
      if (point) acc << "MUL " << x << ", " << x << ", att" << sl.g << "." << sl.c << ";\n";
    }
    if (i > 0) {
      acc << "MAD sum.xyz, " << x << ", " << li << "color, sum;\n";
    } else if (ambient) {
      acc << "MAD sum.xyz, " << x << ", " << li << "color, ambient_light;\n";
    } else {
      acc << "MUL sum.xyz, " << x << ", " << li << "color;\n";
    }
  }
  if (n_lights == 0) {
    acc << (ambient ? "MOV sum.xyz, ambient_light;\n" : "SUB sum.xyz, albedo, albedo;  # 0\n");
  }

  std::string notes;
  for (const std::string& n : out.notes) notes += "# note: " + n + "\n";
  std::string temp_list;
  for (const std::string& t : temps) temp_list += (temp_list.empty() ? "" : ", ") + t;
  out.fragment =
      gl::fill_template(gl::read_shader_source("legacy_shaders/arb/translucency.fp"),
                        {{"VARIANT", term ? variant.name() : std::string("no translucency term")},
                         {"NOTES", notes},
                         {"ALBEDO", vec4(material.albedo, 1)},
                         {"PARAMS", params.str()},
                         {"TEMPS", temp_list},
                         {"VIEW", view.str()},
                         {"LIGHTS", lights.str()},
                         {"LOBE", lobe.str()},
                         {"ACCUMULATE", acc.str()}},
                        "translucency.fp");
  out.vertex = gl::fill_template(
      gl::read_shader_source("legacy_shaders/arb/translucency.vp"),
      {{"LOBE", vertex_lobe ? vertex_lobe_block(scene, tr, method)
                            : std::string("# (the lobe is computed per pixel)")},
       {"THICKNESS", vertex_thickness
                         ? "# Vertex thickness: the mesh colour times the material's tint.\n"
                           "PARAM tint = " +
                               vec4(tr.tint, 0) + ";\n" +
                               "MUL result.texcoord[2], vertex.color, tint;"
                         : "# (constant thickness: nothing more to pass)"}},
      "translucency.vp");
  return out;
}

}  // namespace lt::arbfp
