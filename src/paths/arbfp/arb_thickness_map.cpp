#include "paths/arbfp/arb_thickness_map.h"

#include "paths/arbfp/arb_emitters.h"

namespace lt::arbfp {

void emit_map_uv(ir::Block& code) {
  code.text("# The maps' UVs (texture coordinate set 1) to the fragment program.\n");
  code.op(ir::Op::MOV, ir::output("result.texcoord[2]"), {ir::attrib("vertex.texcoord[1]")});
}

ir::Reg emit_map_texel(ir::Program& p, ir::Block& decls, ir::Block& code, const MapFetch& f) {
  decls.text(f.declaration);
  const ir::Reg r = p.temp(f.reg);
  code.text(f.comment);
  code.tex(r, ir::attrib("fragment.texcoord[2]"), f.unit, "2D");
  if (f.factor != glm::dvec3(1)) {
    const ir::Reg k = decls.param(f.factor_name, vec4(f.factor, 0));
    code.op(ir::Op::MUL, r.masked("xyz"), {r, k});
  }
  return r;
}

ir::Reg emit_map_thickness(ir::Program& p, ir::Block& decls, ir::Block& code,
                           const glm::dvec3& tint) {
  return emit_map_texel(
      p, decls, code,
      {"T", kThicknessMapUnit, tint, "tint",
       "# T = thickness map at the UV (texture[1], 2D, GL_LINEAR, CLAMP_TO_EDGE) * tint\n",
       "# T: one bilinear fetch of the thickness map, first, so it adds no indirection.\n"});
}

}  // namespace lt::arbfp
