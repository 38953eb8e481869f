#include "paths/arbfp/arb_albedo_map.h"

#include "core/error.h"
#include "paths/arbfp/arb_thickness_map.h"

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
  return emit_map_texel(
      p, decls, code,
      {"A", kAlbedoMapUnit, albedo, "albedo_rgb",
       "# A = albedo map at the UV (texture[2], 2D, linear rgb) * albedo\n",
       "# A: one bilinear fetch of the albedo map, first, so it adds no indirection.\n"});
}

}  // namespace lt::arbfp
