#include "paths/arbfp/arb_thickness_map.h"

#include "paths/arbfp/arb_emitters.h"

namespace lt::arbfp {

void emit_map_uv(ir::Block& code) {
  code.text("# The maps' UVs (texture coordinate set 1) to the fragment program.\n");
  code.op(ir::Op::MOV, ir::output("result.texcoord[2]"), {ir::attrib("vertex.texcoord[1]")});
}

ir::Reg emit_map_thickness(ir::Program& p, ir::Block& decls, ir::Block& code,
                           const glm::dvec3& tint) {
  decls.text("# T = thickness map at the UV (texture[1], 2D, GL_LINEAR, CLAMP_TO_EDGE) * tint\n");
  const ir::Reg T = p.temp("T");
  code.text("# T: one bilinear fetch of the thickness map, first, so it adds no indirection.\n");
  code.tex(T, ir::attrib("fragment.texcoord[2]"), kThicknessMapUnit, "2D");
  if (tint != glm::dvec3(1)) {
    const ir::Reg t = decls.param("tint", vec4(tint, 0));
    code.op(ir::Op::MUL, T.masked("xyz"), {T, t});
  }
  return T;
}

}  // namespace lt::arbfp
