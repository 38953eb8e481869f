#include "paths/arbfp/arb_vertex_program.h"

#include "paths/arbfp/arb_albedo_map.h"
#include "paths/arbfp/arb_lobe.h"
#include "paths/arbfp/arb_thickness_map.h"

namespace lt::arbfp {

using ir::attrib;
using ir::Op;
using ir::output;
using ir::Reg;

namespace {

// The program's own description, at its top (what `ltrender info --source` shows).
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

// pow=mul:vertex: N, V, L, H, t = saturate(dot(V, -H)), the lobe t^p and (lobe * s + a) per
// vertex, into texcoord[kVertexLobeTexcoord + g] (lobe * s + a is linear in the lobe, so
// interpolating it equals applying it to the interpolated lobe). Every hard-case convention of
// src/model/translucency.h holds at the vertices; between them the lobe is Gouraud-interpolated
// (also for point lights, whose L is taken at the vertex here, like the combiners path), which is
// this variant's error. On a lobe-ramp material only t, unsaturated: the fragment program reads
// the ramp at the interpolated t, whose CLAMP_TO_EDGE saturates it per pixel as the model does
// (saturating per vertex would move the lobe's edge).
void emit_vertex_lobe(ir::Program& p, const Key& k, std::vector<std::string>& notes) {
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
  LobeInput in{decls, code, s, k.variant, k.tr, k.lights, tv, lobe, notes, {}};
  lobe_mul_vertex(in, k.method);
  code.text("# lobe * s + a, to the fragment program.\n");
  for (size_t g = 0; g < k.groups; ++g) {
    const Reg out = output("result." + vertex_lobe_texcoord(g));
    emit_scale_and_ambient(code, out.masked(group_mask(g, k.lights)), lobe[g], scale[g], s.material,
                           k.tr.ambient != 0);
  }
  code.text("\n");
}

}  // namespace

ir::Program vertex_program(const Key& k, std::vector<std::string>& notes) {
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
    emit_vertex_lobe(p, k, notes);
  } else {
    p.block().text("# (the lobe is computed per pixel)\n");
  }
  return p;
}

}  // namespace lt::arbfp
