// The lobe t^p, one function per method of --variant (arb_variant.h): each writes its constants
// into the declarations and its code into the lobe section of the program, for every light at
// once, and says where each light's lobe ended up.
#pragma once

#include <string>
#include <vector>

#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_variant.h"

namespace lt::arbfp {

// What a method reads and writes. t of light i is read_lane(tv, i); the packed methods leave
// t^p in the same lane of lobe.
struct LobeInput {
  ir::Block& decls;  // PARAMs, before the TEMP statement
  ir::Block& code;   // the lobe section
  const Shading& s;  // r, H, L, material
  const PowVariant& variant;
  const Translucency& tr;
  size_t lights;
  std::vector<ir::Reg> tv, lobe;  // per group of four lights
  bool any_point;                 // L is declared (a register the LUT may reuse)
  std::vector<std::string>& notes;
  std::vector<ir::Reg> addend;  // lobe_mul only: per group, added to t^p (empty: none)
};

// Where light i's t^p is: a lane of lobe (the packed methods), or one register per light (the
// LUT's TEX results, see lobe_lut).
using LobeLanes = std::vector<ir::Reg>;

// Fragment programs.
LobeLanes lobe_exact(LobeInput& in);
LobeLanes lobe_lut(LobeInput& in, const model::PowerLut& lut);
LobeLanes lobe_sg(LobeInput& in);
LobeLanes lobe_sg_simplified(LobeInput& in);
LobeLanes lobe_sg_fitted(LobeInput& in);
// Repeated squaring, in either program.
LobeLanes lobe_mul(LobeInput& in);
// pow=mul:vertex, the vertex program's lobe: lobe_mul or, for a non-integer p (`method` Exact
// after the fallback), POW masked by (t > 0) for 0^p = 0 (vertex programs have no CMP).
LobeLanes lobe_mul_vertex(LobeInput& in, PowMethod method);

}  // namespace lt::arbfp
