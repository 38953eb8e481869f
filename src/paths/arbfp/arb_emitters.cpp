#include "paths/arbfp/arb_emitters.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "model/translucency.h"

namespace lt::arbfp {

using ir::Op;
using ir::Reg;

std::string vec4(const glm::dvec3& v, double w) {
  return ir::vec4(v.x, v.y, v.z, w);
}

size_t group_count(size_t lights) {
  return (lights + 3) / 4;
}

std::string component(size_t light) {
  return std::string(1, "xyzw"[light % 4]);
}

std::string group_mask(size_t group, size_t lights) {
  return std::string("xyzw").substr(0, std::min<size_t>(4, lights - group * 4));
}

Reg read_lane(const std::vector<Reg>& groups, size_t light) {
  return groups[light / 4].swz(component(light));
}

Reg write_lane(const std::vector<Reg>& groups, size_t light) {
  return groups[light / 4].masked(component(light));
}

namespace {

// The guard values, each named once (from src/model/translucency.h where the model has them).
const double kInvNormalMax = 1 / model::kMinNormalLength;
const double kNormalLengthSqMin = model::kMinNormalLength * model::kMinNormalLength;
const double kAttenuationMin = model::kMinAttenuationDenominator;
const double kInvLengthMax = 1e30;  // finite, so 0 * 1e30 = 0 where 0 * RSQ(0) would be NaN
const double kSaturateMax = 1;

// The programs write the guards as powers of ten ("1e-12", "1"): one literal per guard, checked.
std::string power_of_ten(double v) {
  const int e = static_cast<int>(std::lround(std::log10(v)));
  LT_CHECK(static_cast<float>(std::pow(10.0, e)) == static_cast<float>(v),
           "a guard is not a power of ten");
  return e == 0 ? "1" : "1e" + std::to_string(e);
}

}  // namespace

Guards declare_guards(ir::Block& decls) {
  const bool vertex = decls.kind() == ir::ProgramKind::Vertex;
  const double z = vertex ? kSaturateMax : kAttenuationMin;
  const std::string values = power_of_ten(kInvNormalMax) + ", " + power_of_ten(kNormalLengthSqMin) +
                             ", " + power_of_ten(z) + ", " + power_of_ten(kInvLengthMax);
  if (vertex) {
    decls.text(
        "# guard = the fragment program's (x, y: zero normal; w: 1/|v| clamp so 0 * 1e30 = 0\n"
        "# where IEEE would give 0 * inf = NaN); z = 1, the upper bound of saturate.\n");
  } else {
    decls.text(
        "# guard = (" + values +
        "), the model's hard-case conventions (src/model/translucency.h):\n"
        "#  x  RSQ(0) is +inf: clamping the normal's 1/|n| to 1e6 (= 1/kMinNormalLength) keeps "
        "the\n"
        "#     zero-normal mask a multiply of finite values (0 * inf would be NaN).\n"
        "#  y  kMinNormalLength^2: an interpolated normal shorter than 1e-6 is \"no normal\" (N = "
        "0).\n"
        "#  z  kMinAttenuationDenominator: a point light at distance 0 with kc = 0 gives 1e6, "
        "never inf.\n"
        "#  w  clamp of 1/|H| (normalised H only): normalize(0) := 0 because 0 * 1e30 = 0.\n");
  }
  const Reg g = decls.param("guard", "{" + values + "}");
  Guards out{g.swz("x"), g.swz("y"), {}, {}, g.swz("w")};
  (vertex ? out.one : out.attenuation_min) = g.swz("z");
  return out;
}

MaterialParams declare_material(ir::Block& decls, const Translucency& tr) {
  decls.text("# material = (distortion d, power p, lt ambient a, 0)\n");
  const Reg m = decls.param("material", ir::vec4(tr.distortion, tr.power, tr.ambient, 0));
  return {m.swz("x"), m.swz("y"), m.swz("z"), m.swz("w")};
}

Reg declare_orthographic_view(ir::Block& decls, const Scene& scene) {
  decls.text("# orthographic: every view ray is parallel, V = -forward\n");
  return decls.param("V", vec4(-scene.camera.forward(), 0));
}

LightList scene_lights(const Scene& scene, const LightNumbers& numbers) {
  LightList out{scene.lights, {}, scene.camera.eye};
  for (size_t i = 0; i < scene.lights.size(); ++i)
    out.scene_index.push_back(light_number(numbers, i));
  return out;
}

Reg declare_light_vector(ir::Block& decls, const LightList& lights, size_t light) {
  const Light& l = lights[light];
  const std::string prefix = lights.name(light) + "_";
  if (l.type == Light::Type::Directional) {
    return decls.param(prefix + "L", vec4(-l.direction, 0), "-direction");
  }
  return decls.param(prefix + "position", vec4(l.position - lights.eye, 0), "camera-relative");
}

std::array<double, 4> light_scales(const LightList& lights, size_t group) {
  std::array<double, 4> s = {0, 0, 0, 0};
  for (size_t i = group * 4; i < std::min(lights.size(), group * 4 + 4); ++i) {
    s[i % 4] = lights[i].translucency_scale;
  }
  return s;
}

Reg declare_scale(ir::Block& decls, const LightList& lights, size_t group) {
  const std::array<double, 4> s = light_scales(lights, group);
  return decls.param("scale" + std::to_string(group), ir::vec4(s[0], s[1], s[2], s[3]),
                     "s per light");
}

void emit_normal(ir::Block& code, const Shading& s, const Reg& n) {
  const Reg& r = s.r;
  code.op(Op::DP3, r.masked("x"), {n, n});
  code.op(Op::RSQ, r.masked("y"), {r.swz("x")});
  if (!s.zero_normal_guard) {
    code.op(Op::MUL, s.N.masked("xyz"), {n, r.swz("y")}, "no zero normal in this scene");
    return;
  }
  // RSQ(0) = +inf, clamped so the mask below multiplies finite values.
  code.op(Op::MIN, r.masked("y"), {r.swz("y"), s.guard.inv_normal_max});
  code.op(Op::SGE, r.masked("z"), {r.swz("x"), s.guard.normal_length_sq_min});
  code.op(Op::MUL, r.masked("y"), {r.swz("y"), r.swz("z")});
  code.op(Op::MUL, s.N.masked("xyz"), {n, r.swz("y")});
}

namespace {

// dst.xyz = src / |src|; with a clamp of 1/|src| (guard.w), 0 for src = 0 instead of NaN.
void emit_normalize(ir::Block& code, const Reg& dst, const Reg& src, bool clamp,
                    const Guards& guard) {
  Reg length_of = src;
  length_of.negate = false;  // |-v| = |v|
  code.op(Op::DP3, dst.masked("w"), {length_of, length_of});
  code.op(Op::RSQ, dst.masked("w"), {dst.swz("w")});
  if (clamp) code.op(Op::MIN, dst.masked("w"), {dst.swz("w"), guard.inv_length_max});
  code.op(Op::MUL, dst.masked("xyz"), {src, dst.swz("w")});
}

void emit_point_light_direction(ir::Block& code, const Shading& s, const Reg& position,
                                bool distance_zero_guard) {
  const bool vertex = code.kind() == ir::ProgramKind::Vertex;
  const Reg &L = s.L, &r = s.r;
  code.op(Op::SUB, L.masked("xyz"), {position, s.P});
  code.op(Op::DP3, L.masked("w"), {L, L});
  code.op(Op::RSQ, r.masked("x"), {L.swz("w")});
  if (vertex) {
    // No CMP in a vertex program: the clamp makes L = 0 (not NaN) at distance 0, and the
    // (-dist^2 >= 0) mask adds N there.
    code.op(Op::MIN, r.masked("x"), {r.swz("x"), s.guard.inv_length_max});
    code.op(Op::MUL, L.masked("xyz"), {L, r.swz("x")});
    code.op(Op::SGE, r.masked("y"), {-L.swz("w"), s.material.zero});
    code.op(Op::MAD, L.masked("xyz"), {s.N, r.swz("y"), L});
  } else if (!distance_zero_guard) {
    code.op(Op::MUL, L.masked("xyz"), {L, r.swz("x")}, "the light touches no surface");
  } else {
    code.op(Op::MUL, L.masked("xyz"), {L, r.swz("x")});
    code.text(
        "# dist^2 = 0 made L = 0 * inf = NaN above: CMP selects N instead (-dist^2 < 0 is "
        "false).\n");
    code.op(Op::CMP, L.masked("xyz"), {-L.swz("w"), L, s.N});
  }
}

}  // namespace

void emit_view_vector(ir::Block& code, const Shading& s) {
  // No rasterised point is at the eye (near > 0), but a clipped triangle's vertex can be: there
  // the vertex program makes V = 0 (t = 0) instead of 0 * inf.
  const bool vertex = code.kind() == ir::ProgramKind::Vertex;
  code.text(vertex ? "# V = normalize(-P), 0 for a vertex at the eye (1/|P| clamped to 1e30).\n"
                   : "# V = normalize(-P): the eye is the origin of camera-relative space.\n");
  emit_normalize(code, s.V, -s.P, vertex, s.guard);
}

Reg emit_light_direction(ir::Block& code, const Shading& s, const LightList& lights, size_t light,
                         const Reg& light_vector, bool distance_zero_guard) {
  const std::string name = "# light " + std::to_string(lights.scene_index[light]);
  if (lights[light].type == Light::Type::Directional) {
    code.text(name + ": directional\n");
    return light_vector;
  }
  if (code.kind() == ir::ProgramKind::Vertex) {
    code.text(name +
              ": point, L at the vertex. L = (position - P) / dist, and L = N at distance 0:\n"
              "# there 0 * min(RSQ(0), 1e30) = 0, and the SGE mask adds N.\n");
  } else {
    code.text(name + ": point. L = (position - P) / dist, and L = N at distance 0.\n");
  }
  emit_point_light_direction(code, s, light_vector, distance_zero_guard);
  return s.L;
}

void emit_t(ir::Block& code, const Shading& s, const Reg& L, bool normalize_h, const Reg& t) {
  code.op(Op::MAD, s.H.masked("xyz"), {s.N, s.material.distortion, L});
  if (normalize_h) {
    code.text("# normalised H on request: normalize(0) := 0 (1/|H| clamped to 1e30).\n");
    emit_normalize(code, s.H, s.H, true, s.guard);
  }
  if (code.kind() == ir::ProgramKind::Vertex) {
    code.op(Op::DP3, t, {s.V, -s.H});
  } else {
    code.op_sat(Op::DP3, t, {s.V, -s.H});
  }
}

// One MUL per bit after the leading one, plus one per set bit; no extra register (t stays in
// tv[g]). Both program kinds have MUL, MAD, ADD and MOV.
void emit_mul_chain(ir::Block& code, unsigned long k, const std::vector<Reg>& tv,
                    const std::vector<Reg>& lobe, size_t lights, const std::vector<Reg>& addend) {
  int top = 0;
  while ((k >> (top + 1)) != 0) ++top;
  for (size_t g = 0; g < tv.size(); ++g) {
    const Reg dst = lobe[g].masked(group_mask(g, lights));
    std::vector<std::pair<Reg, Reg>> steps;  // the factors of each MUL
    Reg cur = tv[g];
    for (int b = top - 1; b >= 0; --b) {
      steps.push_back({cur, cur});
      cur = lobe[g];
      if ((k >> b) & 1) steps.push_back({lobe[g], tv[g]});
    }
    for (size_t i = 0; i < steps.size(); ++i) {
      const auto& [x, y] = steps[i];
      if (i + 1 == steps.size() && !addend.empty()) {
        code.op(Op::MAD, dst, {x, y, addend[g]});
      } else {
        code.op(Op::MUL, dst, {x, y});
      }
    }
    if (!steps.empty()) continue;
    if (addend.empty()) {
      code.op(Op::MOV, dst, {tv[g]}, "p = 1");
    } else {
      code.op(Op::ADD, dst, {tv[g], addend[g]}, "p = 1");
    }
  }
}

void emit_scale_and_ambient(ir::Block& code, const Reg& dst, const Reg& lobe, const Reg& scale,
                            const MaterialParams& m, bool has_ambient) {
  if (has_ambient) {
    code.op(Op::MAD, dst, {lobe, scale, m.ambient});
  } else {
    code.op(Op::MUL, dst, {lobe, scale}, "a = 0");
  }
}

}  // namespace lt::arbfp
