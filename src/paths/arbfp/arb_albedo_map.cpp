#include "paths/arbfp/arb_albedo_map.h"

#include "core/error.h"
#include "paths/arbfp/arb_emitters.h"

namespace lt::arbfp {

void check_albedo_map_texcoord(const Material& material, const std::string& scene_file) {
  if (!material.albedo_map || !material.translucency ||
      material.translucency->thickness_source != ThicknessSource::Vertex)
    return;
  throw InputError(scene_file, "materials." + material.name + ".albedo_map",
                   "arbfp: the albedo map's UVs and the vertex thickness would share "
                   "texcoord[2]; give the material a constant thickness or a thickness map");
}

ir::Reg emit_albedo_map(ir::Program& p, ir::Block& decls, ir::Block& code,
                        const glm::dvec3& albedo) {
  decls.text("# A = albedo map at the UV (texture[2], 2D, linear rgb) * albedo\n");
  const ir::Reg A = p.temp("A");
  code.text("# A: one bilinear fetch of the albedo map, first, so it adds no indirection.\n");
  code.tex(A, ir::attrib("fragment.texcoord[2]"), kAlbedoMapUnit, "2D");
  if (albedo != glm::dvec3(1)) {
    const ir::Reg a = decls.param("albedo_rgb", vec4(albedo, 0));
    code.op(ir::Op::MUL, A.masked("xyz"), {A, a});
  }
  return A;
}

}  // namespace lt::arbfp
