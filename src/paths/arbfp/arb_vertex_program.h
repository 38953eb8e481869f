// The arbfp path's vertex program for one state key (arb_key.h).
#pragma once

#include <string>
#include <vector>

#include "arb/arb_ir.h"
#include "paths/arbfp/arb_key.h"

namespace lt::arbfp {

// Shading is per pixel: the vertex program hands the fragment program the camera-relative
// position, the normal and, when the material reads it, the vertex thickness; with
// pow=mul:vertex it computes t and the lobe too. Appends to `notes` what its lobe method adds.
ir::Program vertex_program(const Key& k, std::vector<std::string>& notes);

}  // namespace lt::arbfp
