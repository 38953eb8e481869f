#include "paths/arbfp/arb_generator.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/error.h"
#include "gl/program.h"
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

std::string PowVariant::name() const {
  switch (method) {
    case PowMethod::Exact:
      return "pow=exact";
    case PowMethod::Lut:
      return "pow=lut:" + std::to_string(lut_size) + ":" + model::to_string(lut_format);
    case PowMethod::Sg:
      return "pow=sg";
    case PowMethod::SgSimplified:
      return "pow=sg-simplified";
    case PowMethod::SgFitted:
      return "pow=sg-fitted";
    case PowMethod::Mul:
      return "pow=mul";
  }
  return "?";
}

PowVariant parse_variant(const std::string& name) {
  PowVariant v;
  const std::string prefix = "pow=";
  if (name.rfind(prefix, 0) != 0) {
    throw InputError("--variant", name, "arbfp variants start with pow=");
  }
  const std::string m = name.substr(prefix.size());
  if (m == "exact") return v;
  if (m == "sg") return {PowMethod::Sg};
  if (m == "sg-simplified") return {PowMethod::SgSimplified};
  if (m == "sg-fitted") return {PowMethod::SgFitted};
  if (m == "mul") return {PowMethod::Mul};
  // lut:N:FORMAT
  int size = 0;
  char format[8] = {};
  if (std::sscanf(m.c_str(), "lut:%d:%7s", &size, format) == 2 && size >= 2 && size <= 4096) {
    v.method = PowMethod::Lut;
    v.lut_size = size;
    const std::string f = format;
    if (f == "u8")
      v.lut_format = model::LutFormat::U8;
    else if (f == "f16")
      v.lut_format = model::LutFormat::F16;
    else if (f == "f32")
      v.lut_format = model::LutFormat::F32;
    else
      throw InputError("--variant", name, "LUT format must be u8, f16 or f32");
    if (v.name() == name) return v;
  }
  throw InputError("--variant", name,
                   "unknown arbfp variant (pow=exact, pow=lut:N:u8|f16|f32 with 2 <= N <= 4096, "
                   "pow=sg, pow=sg-simplified, pow=sg-fitted, pow=mul)");
}

double sg_exponent(double p) {
  return p / std::log(2.0) + 1 / std::log(2.0);
}

double fit_sg_exponent(double p) {
  // Max error over a dense t grid; the fitted curve is smooth, 4097 samples resolve its peak.
  auto max_error = [p](double n) {
    double e = 0;
    for (int i = 0; i <= 4096; ++i) {
      const double t = i / 4096.0;
      e = std::max(e, std::abs(std::exp2(n * (t - 1)) - model::lobe(t, p)));
    }
    return e;
  };
  // Coarse scan over [0, 2 n'_sg + 8], then golden-section refinement around the best sample
  // (the max error is unimodal near its minimum, not necessarily globally).
  const double hi = 2 * sg_exponent(p) + 8;
  const int steps = 200;
  int best = 0;
  double best_e = max_error(0);
  for (int i = 1; i <= steps; ++i) {
    const double e = max_error(hi * i / steps);
    if (e < best_e) best_e = e, best = i;
  }
  double a = hi * std::max(best - 1, 0) / steps, b = hi * std::min(best + 1, steps) / steps;
  const double g = (std::sqrt(5.0) - 1) / 2;
  for (int it = 0; it < 60; ++it) {
    const double c = b - g * (b - a), d = a + g * (b - a);
    if (max_error(c) < max_error(d))
      b = d;
    else
      a = c;
  }
  return (a + b) / 2;
}

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

  PowMethod method = variant.method;
  if (term && !flat_lobe && method == PowMethod::Mul && !is_integer_power(tr.power)) {
    out.notes.push_back("pow=mul: power " + num(tr.power) +
                        " is not an integer, exact POW used instead");
    method = PowMethod::Exact;
  }
  if (flat_lobe) out.notes.push_back("power 0: the lobe is 1 everywhere (0^0 := 1), no pow");

  std::ostringstream params, view, lights, lobe, acc;
  std::vector<std::string> temps = {"r", "N", "sum"};
  if (term && !flat_lobe) temps.push_back("H");
  if (any_point) temps.push_back("L");
  for (size_t g = 0; g < groups; ++g) {
    const std::string s = std::to_string(g);
    temps.push_back("diffuse" + s);
    if (term && !flat_lobe) temps.push_back("tv" + s), temps.push_back("lobe" + s);
    if (any_point) temps.push_back("att" + s);
  }
  if (term) temps.push_back("acc");

  // Constants: material, view, thickness, lobe parameters.
  if (term) {
    params << "# material = (distortion d, power p, lt ambient a, 0)\n"
           << "PARAM material = " << vec4(tr.distortion, tr.power, tr.ambient, 0) << ";\n";
    if (vertex_thickness) {
      // T = vertex colour * tint is multiplied in the vertex program: the tint is constant, so
      // interpolating the product equals the product of the interpolation, and the fragment
      // program saves one MUL per pixel.
      params << "# T = fragment.texcoord[2]: vertex colour * tint\n";
    } else {
      params << "# constant thickness * tint\n"
             << "PARAM T = " << vec4(tr.thickness * tr.tint, 0) << ";\n";
    }
    if (!flat_lobe) {
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
    if (term && !flat_lobe) {
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
    lobe_reg[i].append("lobe").append(slot(i).g).append(".").append(slot(i).c);
  }
  if (term) {
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
      double n = sg_exponent(tr.power);
      if (method == PowMethod::SgSimplified) n = tr.power;
      if (method == PowMethod::SgFitted) {
        n = fit_sg_exponent(tr.power);
        out.notes.push_back("pow=sg-fitted: n' = " + num(n) + " for p = " + num(tr.power) +
                            " (sg: " + num(sg_exponent(tr.power)) + ")");
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
      // Left-to-right binary exponentiation: one MUL per bit after the leading one, plus one per
      // set bit; no extra register (t stays in tv<g>).
      const auto k = static_cast<unsigned long>(tr.power);
      int top = 0;
      while ((k >> (top + 1)) != 0) ++top;
      lobe << "# pow=mul: t^" << k << " by repeated squaring (exact up to float rounding).\n";
      for (size_t g = 0; g < groups; ++g) {
        const std::string lg = "lobe" + std::to_string(g), tg = "tv" + std::to_string(g);
        const std::string m = group_mask(g, n_lights);
        std::string cur = tg;
        for (int b = top - 1; b >= 0; --b) {
          lobe << "MUL " << lg << m << ", " << cur << ", " << cur << ";\n";
          cur = lg;
          if ((k >> b) & 1) lobe << "MUL " << lg << m << ", " << lg << ", " << tg << ";\n";
        }
        if (cur == tg) lobe << "MOV " << lg << m << ", " << tg << ";  # p = 1\n";
      }
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
      params << "PARAM scale" << g << " = " << vec4(s[0], s[1], s[2], s[3]) << ";  # s per light\n";
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
      if (!flat_lobe && method == PowMethod::Lut) {
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
      {{"THICKNESS", vertex_thickness
                         ? "# Vertex thickness: the mesh colour times the material's tint.\n"
                           "PARAM tint = " +
                               vec4(tr.tint, 0) + ";\n" +
                               "MUL result.texcoord[2], vertex.color, tint;"
                         : "# (constant thickness: nothing more to pass)"}},
      "translucency.vp");
  return out;
}

}  // namespace lt::arbfp
