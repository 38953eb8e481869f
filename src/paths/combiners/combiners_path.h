// The combiners path: no shaders at all, only GL 1.3 fixed-function state (texture combiner
// stages from combiners/*.comb, vertex colours, colour sum, additive passes), the way the seed's
// Wii version and DX7-class hardware would draw the translucency term. Per-vertex work is done on
// the CPU each frame and streamed as vertex arrays, as a fixed-function engine would.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "combiner/combiner_program.h"
#include "paths/path.h"

namespace lt {

const PathInfo& combiners_path_info();

// The variants: where t (or the whole lobe) comes from.
enum class CombinersVariant {
  TVertex,   // "t=vertex": t per vertex on the CPU (the default)
  TTexgen,   // "t=texgen": t by texgen NORMAL_MAP and the texture matrix (texgen_matrix.h)
  LobeCube,  // "lobe=cube": a cube map by the normal holds the lobe (cube_lobe.h)
};
// The variant a --variant name names ("" = the default); throws InputError("--variant", name,
// "path combiners has no such variant (valid: ...)").
CombinersVariant parse_combiners_variant(const std::string& name);

// What one pass draws, chosen once by plan_combiners; every later decision reads the kind.
enum class PassKind {
  DiffuseOnly,     // a material without translucency: the diffuse sum per vertex
  LobeVertex,      // the lobe table (lobe_table.h) at a per-vertex t
  LobeTexgen,      // the lobe table at t from texgen NORMAL_MAP and the texture matrix
  LobeCube,        // the lobe from a cube map of the normal (its alpha), thickness per vertex
  LobeCubeFull,    // the whole term in the cube map (constant thickness)
  LobeVertexMap,   // a thickness map's material: the table at a per-vertex t, the map on unit 1
  AlbedoModulate,  // an albedo map's material, last: the framebuffer times the map (blend)
};
// Its program in combiners/ ("lobe_vertex.comb").
const char* program_file(PassKind kind);
inline bool uses_cube(PassKind k) {
  return k == PassKind::LobeCube || k == PassKind::LobeCubeFull;
}

// The plan for one scene: which program each pass of each material uses (shared by the path and
// the budget checker, so both count the same thing). Pass l of a translucent material draws
// light l and adds onto the passes before it; a material without translucency takes one pass.
// A material with an albedo map takes one more, last: AlbedoModulate.
struct CombinerMaterialPlan {
  int material = 0;
  bool used = false;                                        // some object draws with it
  std::vector<PassKind> pass_kinds;                         // per pass
  std::map<PassKind, combiners::CombinerProgram> programs;  // the programs those kinds use

  int passes() const { return static_cast<int>(pass_kinds.size()); }
  PassKind kind(int pass) const { return pass_kinds[static_cast<size_t>(pass)]; }
  const combiners::CombinerProgram& program(int pass) const { return programs.at(kind(pass)); }
};
// t=texgen serves only scenes
// texgen_applicable accepts (else t=vertex); lobe=cube serves directional lights (point lights
// get t=vertex passes, and so does an rgb lobe ramp with per-vertex thickness: lobe_cube.comb
// holds the lobe in the cube's one alpha channel). A lobe ramp rides in every program's lobe
// (the table, or the cube baked from it).
std::vector<CombinerMaterialPlan> plan_combiners(const Scene& scene, CombinersVariant variant);

}  // namespace lt
