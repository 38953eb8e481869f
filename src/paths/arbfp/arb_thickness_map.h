// A thickness map in the ARB programs: the vertex program passes the mesh's UVs on, the fragment
// program fetches T with one TEX (2D, texture unit 1) as its first instruction. Kept apart from
// the generator's light loop: the generator calls these two where it decides T.
#pragma once

#include <glm/glm.hpp>

#include "arb/arb_ir.h"

namespace lt::arbfp {

// texture[1]: unit 0 is the lobe table's (the power LUT or a lobe ramp, kLobeTableUnit in
// arb_lobe.h). The UVs arrive as vertex.texcoord[1]
// (gl/scene_geometry.h) and travel in result.texcoord[2], the vertex thickness's varying, which
// a map material does not read.
inline constexpr int kThicknessMapUnit = 1;

// Vertex program: MOV result.texcoord[2], vertex.texcoord[1] (the albedo map reads them too,
// arb_albedo_map.h).
void emit_map_uv(ir::Block& code);

// One map's texel at the UVs times a constant: TEX `reg`, fragment.texcoord[2], texture[unit],
// 2D, then MUL reg.xyz by `factor` (the PARAM `factor_name`) unless it is 1. The thickness map's
// and the albedo map's (arb_albedo_map.h) fetch.
struct MapFetch {
  const char* reg;
  int unit;
  glm::dvec3 factor;
  const char* factor_name;
  const char* declaration;  // the comment among the declarations
  const char* comment;      // the comment before the TEX
};
ir::Reg emit_map_texel(ir::Program& p, ir::Block& decls, ir::Block& code, const MapFetch& fetch);

// Fragment program: TEX T, fragment.texcoord[2], texture[1], 2D, then MUL T.xyz by the tint
// unless it is 1. Emitted before any ALU instruction, the fetch reads an input directly, so it
// is in the first texture indirection (ARB_fragment_program issue 24) and adds none: the LUT's
// or the ramp's TEX, which read a computed t, stay the second.
ir::Reg emit_map_thickness(ir::Program& p, ir::Block& decls, ir::Block& code,
                           const glm::dvec3& tint);

}  // namespace lt::arbfp
