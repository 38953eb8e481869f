#include "paths/arbfp/arb_pack.h"

#include <algorithm>

#include "paths/arbfp/arb_view_dots.h"

namespace lt::arbfp {

using ir::Op;
using ir::Reg;

namespace {

// One value per lane of group g ("{a, b, c, d}", 0 past the last light).
template <typename F>
std::string lanes_of(const LightList& lights, size_t group, F value) {
  std::array<double, 4> v = {0, 0, 0, 0};
  for (size_t i = group * 4; i < std::min(lights.size(), group * 4 + 4); ++i) {
    v[i % 4] = value(lights[i]);
  }
  return ir::vec4(v[0], v[1], v[2], v[3]);
}

std::string names_of(const LightList& lights, size_t group) {
  std::string s;
  for (size_t i = group * 4; i < std::min(lights.size(), group * 4 + 4); ++i) {
    s += (s.empty() ? "" : ", ") + lights.name(i);
  }
  return s;
}

// Each lane of `mask` through a scalar opcode (RSQ, RCP read one component).
void per_lane(ir::Block& code, Op op, const Reg& dst, const Reg& src, const std::string& mask) {
  for (char c : mask) {
    const std::string lane(1, c);
    code.op(op, dst.masked(lane), {src.swz(lane)});
  }
}

// reg.mask = row_x * a.x + row_y * a.y + row_z * a.z: a three-vector a against four lights'
// vectors, one lane per light.
void dot_rows(ir::Block& code, const Reg& reg, const std::string& mask,
              const std::array<Reg, 3>& rows, const Reg& a, bool saturate) {
  const Reg dst = reg.masked(mask);
  code.op(Op::MUL, dst, {rows[0], a.swz("x")});
  code.op(Op::MAD, dst, {rows[1], a.swz("y"), reg});
  if (saturate) {
    code.op_sat(Op::MAD, dst, {rows[2], a.swz("z"), reg});
  } else {
    code.op(Op::MAD, dst, {rows[2], a.swz("z"), reg});
  }
}

}  // namespace

PackedRows declare_packed_rows(ir::Block& decls, const LightList& lights, size_t group) {
  const std::string g = std::to_string(group);
  const bool point = lights[group * 4].type == Light::Type::Point;
  const std::string what = names_of(lights, group);
  PackedRows r;
  if (point) {
    const glm::dvec3 e = lights.eye;
    r.x = decls.param("pos_x" + g,
                      lanes_of(lights, group, [&](const Light& l) { return l.position.x - e.x; }),
                      "camera-relative positions of " + what);
    r.y = decls.param("pos_y" + g,
                      lanes_of(lights, group, [&](const Light& l) { return l.position.y - e.y; }));
    r.z = decls.param("pos_z" + g,
                      lanes_of(lights, group, [&](const Light& l) { return l.position.z - e.z; }));
    r.kc = decls.param("kc" + g, lanes_of(lights, group, [](const Light& l) { return l.kc; }),
                       "attenuation kc, kl, kq of " + what);
    r.kl = decls.param("kl" + g, lanes_of(lights, group, [](const Light& l) { return l.kl; }));
    r.kq = decls.param("kq" + g, lanes_of(lights, group, [](const Light& l) { return l.kq; }));
  } else {
    r.x = decls.param("L_x" + g,
                      lanes_of(lights, group, [](const Light& l) { return -l.direction.x; }),
                      "L = -direction of " + what);
    r.y = decls.param("L_y" + g,
                      lanes_of(lights, group, [](const Light& l) { return -l.direction.y; }));
    r.z = decls.param("L_z" + g,
                      lanes_of(lights, group, [](const Light& l) { return -l.direction.z; }));
  }
  return r;
}

std::array<Reg, 3> declare_colour_rows(ir::Block& decls, const LightList& lights, size_t group,
                                       bool scaled) {
  const std::string name = std::string(scaled ? "color_s_" : "color_");
  const std::string g = std::to_string(group);
  const auto row = [&](int c) {
    return lanes_of(lights, group, [&](const Light& l) {
      return l.color[c] * (scaled ? l.translucency_scale : 1.0);
    });
  };
  return {decls.param(name + "r" + g, row(0),
                      std::string(scaled ? "s * colours" : "colours") + " of " +
                          names_of(lights, group) + ", transposed"),
          decls.param(name + "g" + g, row(1)), decls.param(name + "b" + g, row(2))};
}

bool group_has_one_kind(const LightList& lights, size_t group) {
  for (size_t i = group * 4; i < std::min(lights.size(), group * 4 + 4); ++i) {
    if (lights[i].type != lights[group * 4].type) return false;
  }
  return true;
}

void emit_packed_group(ir::Block& code, const Shading& s, const PackedRows& rows,
                       const PackedGroup& g) {
  const std::string& m = g.mask;
  const Reg diffuse = g.diffuse.masked(m), tv = g.tv.valid() ? g.tv.masked(m) : Reg{};
  if (!g.point) {
    code.text("# N.L and t = saturate(-(V.L) - d (N.V)) of each light at once (H = L + N d).\n");
    dot_rows(code, g.diffuse, m, {rows.x, rows.y, rows.z}, s.N, true);
    if (g.tv.valid() && g.view_dots.valid()) {
      emit_group_view_dot_t(code, m, g.view_dots, g.eye, g.view_addend, g.tv);
    } else if (g.tv.valid()) {
      dot_rows(code, g.tv, m, {rows.x, rows.y, rows.z}, s.V, false);
      code.op_sat(Op::ADD, tv, {-g.tv, -g.dnv});
    }
    return;
  }
  const Reg &P = s.P, &d2 = g.d2, &inv = g.inv;
  const std::array<Reg, 3> d = {g.d[0].masked(m), g.d[1].masked(m), g.d[2].masked(m)};
  code.text(
      "# position - P per light (the x of every light in d_x ...), dist^2, and 1/dist per lane.\n");
  code.op(Op::SUB, d[0], {rows.x, P.swz("x")});
  code.op(Op::SUB, d[1], {rows.y, P.swz("y")});
  code.op(Op::SUB, d[2], {rows.z, P.swz("z")});
  code.op(Op::MUL, d2.masked(m), {g.d[0], g.d[0]});
  code.op(Op::MAD, d2.masked(m), {g.d[1], g.d[1], d2});
  code.op(Op::MAD, d2.masked(m), {g.d[2], g.d[2], d2});
  per_lane(code, Op::RSQ, inv, d2, m);
  if (!g.distance_zero_lanes.empty()) {
    // At dist^2 = 0 the light vector becomes N and 1/dist becomes 1 (RSQ(0) = +inf is
    // replaced, not multiplied): then N.L = N.N, V.L = V.N and dist = 0, the model's L = N.
    code.text("# dist^2 = 0: L = N (CMP selects N and 1/dist = 1 where -dist^2 < 0 is false).\n");
    const std::string& z = g.distance_zero_lanes;
    const char* axes[] = {"x", "y", "z"};
    for (int a = 0; a < 3; ++a) {
      code.op(Op::CMP, g.d[a].masked(z), {-d2, g.d[a], s.N.swz(axes[a])});
    }
    code.op(Op::CMP, inv.masked(z), {-d2, inv, g.one.swz("x")});
  }
  code.text("# N.L = (N . (position - P)) / dist, saturated; t = saturate(-(V.L) - d (N.V)).\n");
  dot_rows(code, g.diffuse, m, {g.d[0], g.d[1], g.d[2]}, s.N, false);
  code.op_sat(Op::MUL, diffuse, {g.diffuse, inv});
  if (g.tv.valid() && g.view_dots.valid()) {
    emit_point_view_dot(code, m, g.view_dots, g.eye, g.tv);
    if (!g.distance_zero_lanes.empty()) {
      // L = N there, so -(V.L) = -(V.N) = (N.P) / |P| (into eye.w, free), times 1/dist = 1.
      code.text("# dist^2 = 0: -(V.L) = (N.P) / |P| in those lanes (L = N).\n");
      code.op(Op::DP3, g.eye.masked("w"), {s.N, P});
      code.op(Op::MUL, g.eye.masked("w"), {g.eye.swz("w"), g.eye.swz("y")});
      code.op(Op::CMP, g.tv.masked(g.distance_zero_lanes), {-d2, g.tv, g.eye.swz("w")});
    }
    code.op_sat(Op::MAD, tv, {g.tv, inv, g.view_addend});
  } else if (g.tv.valid()) {
    dot_rows(code, g.tv, m, {g.d[0], g.d[1], g.d[2]}, s.V, false);
    code.op_sat(Op::MAD, tv, {-g.tv, inv, -g.dnv});
  }
  code.text(
      "# attenuation 1 / (kc + kl dist + kq dist^2), dist = dist^2 / dist (finite: dist^2 > 0 "
      "or\n# 1/dist = 1 above).\n");
  const Reg att = g.att.masked(m);
  code.op(Op::MUL, att, {d2, inv});
  code.op(Op::MAD, att, {g.att, rows.kl, rows.kc});
  code.op(Op::MAD, att, {d2, rows.kq, g.att});
  if (!g.floor_lanes.empty()) {
    code.op(Op::MAX, g.att.masked(g.floor_lanes), {g.att, s.guard.attenuation_min});
  }
  per_lane(code, Op::RCP, g.att, g.att, m);
}

}  // namespace lt::arbfp
