// The lobe t^p, one function per method of --variant (arb_variant.h): each writes its constants
// into the declarations and its code into the lobe section of the program, for every light at
// once, and says where each light's lobe ended up. A material's lobe ramp replaces every method
// (lobe_ramp).
#pragma once

#include <string>
#include <vector>

#include "paths/arbfp/arb_emitters.h"
#include "paths/arbfp/arb_variant.h"

namespace lt::arbfp {

// texture[0]: the lobe's table, the only texture a lobe reads: the power LUT (1D, pow=lut) or the
// material's lobe ramp (2D, one row). Whichever a material has, its programs sample nothing else
// on unit 0 (texture[1] is the thickness map's, arb_thickness_map.h).
inline constexpr int kLobeTableUnit = 0;

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
  std::vector<std::string>& notes;
  std::vector<ir::Reg> addend;  // lobe_mul only: per group, added to t^p (empty: none)
  // lobe_lut only: registers dead when the lobe runs (the generator's lobe_scratch), which its
  // TEX results take before new temporaries are declared (see lobe_ramp).
  std::vector<ir::Reg> scratch = {};
};

// Where light i's t^p is: a lane of lobe (the packed methods), or one register per light (the
// LUT's TEX results, see lobe_lut; a ramp's rgb, see lobe_ramp).
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

// A material's lobe ramp, whatever the variant (the ramp is the curve: no method has anything to
// approximate): one TEX per light of texture[kLobeTableUnit], 2D, at t[i] (a one-component
// source, so the coordinate is (t, t): the ramp is one row high, and CLAMP_TO_EDGE reads that row
// at any v, exactly what (t, 0.5) reads, without the instruction that would build it). Light i's
// lobe is the whole register (rgb; w = 1, unread). Each TEX writes a whole register: a group's
// t register once its last lane is read, else `scratch` (dead by now), else a new temporary.
// Emitted after every ALU instruction of the lights, so the TEXes are one texture indirection
// together (the same rules as lobe_lut's TEXes).
LobeLanes lobe_ramp(ir::Block& code, const std::vector<ir::Reg>& t,
                    const std::vector<ir::Reg>& scratch);

}  // namespace lt::arbfp
