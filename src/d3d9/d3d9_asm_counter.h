// What a Direct3D 9 assembly program uses, counted on its instruction list as fxc counts it:
// instruction slots by the version's table (d3d9_asm_instructions.h), arithmetic and texture
// slots apart for a pixel shader (fxc's "; N ALU, M TEX" and "N instruction slots used (M
// texture, K arithmetic)"), and the registers a profile limits.
#pragma once

#include "d3d9/d3d9_asm_program.h"

namespace lt::d3d9 {

struct Counts {
  int arithmetic = 0;   // slots of arithmetic instructions (fxc's ALU)
  int texture = 0;      // slots of texture instructions (fxc's TEX; texkill is one)
  int flow = 0;         // slots of flow-control instructions
  int temporaries = 0;  // r#: the highest index used + 1, the registers a driver must give
  int constants = 0;    // c#: the highest index read or defined + 1 (relative: its base)
  bool relative_constants = false;  // some c# is relatively addressed: its range is unknown
  int samplers = 0;                 // distinct s# declared or sampled
  int inputs = 0;                   // distinct t# (ps_2_0, ps_2_x) or v# (others) declared or read
  // Pixel shaders: levels of texture reads, 1 + the highest dependent order as "texld - ps_2_0
  // and up" defines it (0 without a texture read); ps_2_0 allows third order, 4 levels.
  int dependent_levels = 0;

  int slots() const { return arithmetic + texture + flow; }
};

Counts count(const Program& program);

}  // namespace lt::d3d9
